// The measured-cost choice behind `auto` and the reused factorization's
// choice of factor: an untried alternative is tried at once, the cheaper one
// is used, the other one is probed every n-th call and takes over when its
// cost drops.
#include <gtest/gtest.h>

#include "core/linear/cheaper_of_two.h"

namespace fissure {
namespace {

TEST(CheaperOfTwo, TriesBothThenUsesTheCheaperAndProbesTheOther) {
  CheaperOfTwo choice(4);
  EXPECT_EQ(choice.pick(), 0);  // nothing measured: the first
  choice.record(0, 2.0);
  EXPECT_EQ(choice.pick(), 1);  // the untried one
  choice.record(1, 1.0);
  EXPECT_EQ(choice.pick(), 1);  // cheaper
  choice.record(1, 1.0);
  EXPECT_EQ(choice.pick(), 0);  // 4th call: probe
  choice.record(0, 2.0);
  for (int call = 5; call <= 7; ++call) EXPECT_EQ(choice.pick(), 1) << call;
  EXPECT_EQ(choice.pick(), 0);  // 8th call: probe again
}

TEST(CheaperOfTwo, FollowsAChangingCost) {
  // The running mean weighs the last measurement by half: when alternative
  // 1 turns dear (1 -> 8 s), one measurement puts its mean (4.5 s) above
  // alternative 0's (2 s).
  CheaperOfTwo choice(1000);
  choice.record(0, 2.0);
  choice.record(1, 1.0);
  EXPECT_EQ(choice.pick(), 1);
  choice.record(1, 8.0);  // mean 4.5
  EXPECT_EQ(choice.pick(), 0);
}

}  // namespace
}  // namespace fissure

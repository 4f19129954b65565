// The measured-cost choice behind `auto`: an untried alternative is tried at
// once, the cheaper one is used, the other one is probed every n-th call (n
// stretched by the ratio of their costs) and takes over when its cost drops.
#include <gtest/gtest.h>

#include <utility>

#include "core/linear/cheaper_of_two.h"

namespace fissure {
namespace {

TEST(CheaperOfTwo, TriesBothThenUsesTheCheaperAndProbesTheOther) {
  CheaperOfTwo choice(4);
  EXPECT_EQ(choice.pick(), 0);  // nothing measured: the first
  choice.record(0, 1.0);
  EXPECT_EQ(choice.pick(), 1);  // the untried one
  choice.record(1, 1.0);
  EXPECT_EQ(choice.pick(), 0);  // a tie: the first
  EXPECT_EQ(choice.pick(), 1);  // 4th call: probe (equal costs: every 4th)
  for (int call = 5; call <= 7; ++call) EXPECT_EQ(choice.pick(), 0) << call;
  EXPECT_EQ(choice.pick(), 1);  // 8th call: probe again
}

TEST(CheaperOfTwo, ProbesADearerAlternativeLessOften) {
  // The interval is probe_every times the ratio of the means, at most four
  // times probe_every: twice as dear, every 8th call; ten times, every 16th.
  for (const auto& [dear, interval] : {std::pair{2.0, 8}, std::pair{10.0, 16}}) {
    CheaperOfTwo choice(4);
    choice.record(0, dear);
    choice.record(1, 1.0);
    int probes = 0, last_probe = 0;
    for (int call = 1; call <= 4 * interval; ++call)
      if (choice.pick() == 0) {
        ++probes;
        EXPECT_EQ(call - last_probe, interval) << "cost ratio " << dear;
        last_probe = call;
      }
    EXPECT_EQ(probes, 4) << "cost ratio " << dear;
  }
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

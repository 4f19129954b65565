// The update by which the DDA system differs from the one the solver last
// factorized (mechanics/dda/factored_contacts.h): the rank-one terms of the
// contacts that changed state, closed, opened, appeared or disappeared since
// must add up to the difference of the assembled systems exactly (to
// rounding), also when the contacts' geometry has moved in between.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/base/errors.h"
#include "mechanics/dda/factored_contacts.h"
#include "tests/support/block_systems.h"

namespace fissure::dda {
namespace {

constexpr SpringConstants kSprings{5e10, 2e10};
const std::vector<double> kFriction{0.0, 0.58};  // per joint: 0 and 30 deg

/// Three free blocks, each pair in contact range.
BlockSparseMatrix pattern() {
  BlockSparseMatrix m;
  const std::vector<std::pair<int, int>> pairs{{0, 1}, {1, 2}, {0, 2}};
  m.set_pattern(3, pairs);
  return m;
}

ContactSlots slots_of(const BlockSparseMatrix& m, int i, int j) {
  ContactSlots s;
  s.dof_i = i;
  s.dof_j = j;
  s.ii = i >= 0 ? m.diagonal_index(i) : -1;
  s.jj = j >= 0 ? m.diagonal_index(j) : -1;
  s.ij = i >= 0 && j >= 0 ? m.find(i, j) : -1;
  s.ji = i >= 0 && j >= 0 ? m.find(j, i) : -1;
  return s;
}

DdaContact contact(ContactKey key, int joint, ContactState state, double slip_sign) {
  DdaContact c;
  c.key = key;
  c.joint = joint;
  c.state = state;
  c.slip_sign = slip_sign;
  for (Vector6* v : {&c.e, &c.g, &c.es, &c.gs, &c.friction_i, &c.friction_j}) v->setRandom();
  return c;
}

/// The contact part of the system, assembled as BlockSystem does.
Eigen::MatrixXd assembled(const std::vector<DdaContact>& contacts,
                          const std::vector<ContactSlots>& slots) {
  BlockSparseMatrix m = pattern();
  m.set_zero();
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(18);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    assemble_contact_springs(contacts[c], slots[c], kSprings, m, rhs);
    assemble_sliding_friction(contacts[c], slots[c], kSprings.normal,
                              friction_coefficient(contacts[c], kFriction), m, rhs);
  }
  Eigen::MatrixXd dense(18, 18);
  Eigen::VectorXd column;
  for (int k = 0; k < 18; ++k) {
    m.multiply(Eigen::VectorXd::Unit(18, k), column);
    dense.col(k) = column;
  }
  return dense;
}

TEST(FactoredContacts, TermsAddUpToTheChangeOfTheAssembledSystem) {
  const BlockSparseMatrix m = pattern();
  const ContactState states[] = {ContactState::Open, ContactState::Locked, ContactState::Sliding};
  std::srand(3);
  // Every pair of states, both slip signs, with and without friction, on a
  // contact between two free blocks and on one against a fixed block.
  for (const ContactState before : states)
    for (const ContactState now : states)
      for (const double slip : {1.0, -1.0})
        for (const int joint : {0, 1})
          for (const int j : {1, -1})
            for (const bool moved : {false, true}) {
              const ContactKey key{0, 2, j < 0 ? 3 : 1, 1};
              const std::vector<ContactSlots> slots{slots_of(m, 0, j)};
              const std::vector<DdaContact> then{contact(key, joint, before, 1.0)};
              std::vector<DdaContact> current{contact(key, joint, now, slip)};
              if (!moved) {  // the same geometry, another state
                current[0] = then[0];
                current[0].state = now;
                current[0].slip_sign = slip;
              }
              FactoredContacts factored;
              factored.record(then, slots);
              factored.contacts_replaced();
              LowRankUpdate terms;
              ASSERT_TRUE(factored.describe(current, slots, kSprings, kFriction, 100, terms));
              // Where the contact's geometry moved in between (new random
              // vectors), a changed contact's terms carry both geometries and
              // an unchanged one is left to the solver (drift).
              const bool changed = before != now || (now == ContactState::Sliding && slip != 1.0);
              const Eigen::MatrixXd expected =
                  changed ? Eigen::MatrixXd(assembled(current, slots) - assembled(then, slots))
                          : Eigen::MatrixXd::Zero(18, 18);
              const double scale = assembled(current, slots).norm() + assembled(then, slots).norm();
              EXPECT_LE((testing::dense(terms, 18) - expected).norm(), 1e-14 * std::max(scale, 1.0))
                  << static_cast<int>(before) << " -> " << static_cast<int>(now) << " slip " << slip
                  << " joint " << joint << " j " << j;
              // At most two terms per changed contact in place (normal and
              // shear, or shear and friction, ...), four if it moved.
              EXPECT_LE(terms.size(), moved ? 4u : 2u);
            }
}

TEST(FactoredContacts, ContactsThatAppearOrDisappearAreTerms) {
  // Recorded: a locked contact 0-1 and a sliding one 1-2. Now: 0-1 gone, 1-2
  // unchanged, a new locked contact 0-2. Same geometry, so the terms are the
  // whole difference.
  const BlockSparseMatrix m = pattern();
  std::srand(5);
  const DdaContact a = contact({0, 0, 1, 2}, 1, ContactState::Locked, 0);
  const DdaContact b = contact({1, 1, 2, 3}, 1, ContactState::Sliding, -1);
  const DdaContact c = contact({0, 3, 2, 0}, 1, ContactState::Locked, 0);
  FactoredContacts factored;
  EXPECT_TRUE(factored.empty());
  factored.record({a, b}, {slots_of(m, 0, 1), slots_of(m, 1, 2)});
  EXPECT_FALSE(factored.empty());
  factored.contacts_replaced();  // a new step's contact list, sorted by key as detection gives it
  const std::vector<DdaContact> now{c, b};
  const std::vector<ContactSlots> now_slots{slots_of(m, 0, 2), slots_of(m, 1, 2)};
  LowRankUpdate terms;
  ASSERT_TRUE(factored.describe(now, now_slots, kSprings, kFriction, 100, terms));
  EXPECT_EQ(terms.size(), 4u);  // c's two springs in, a's two out
  const Eigen::MatrixXd expected =
      assembled(now, now_slots) - assembled({a, b}, {slots_of(m, 0, 1), slots_of(m, 1, 2)});
  EXPECT_LE((testing::dense(terms, 18) - expected).norm(), 1e-14 * expected.norm());
  // More terms than allowed: described as unknown.
  EXPECT_FALSE(factored.describe(now, now_slots, kSprings, kFriction, 3, terms));
  // A list out of key order cannot be matched by merging: an error, not a
  // silently wrong update.
  factored.contacts_replaced();
  EXPECT_THROW(
      factored.describe({b, c}, {now_slots[1], now_slots[0]}, kSprings, kFriction, 100, terms),
      Error);
  // The same for the recorded list.
  factored.record({b, a}, {slots_of(m, 1, 2), slots_of(m, 0, 1)});
  factored.contacts_replaced();
  EXPECT_THROW(factored.describe(now, now_slots, kSprings, kFriction, 100, terms), Error);
}

TEST(FactoredContacts, AContactWithALawTakesItsOwnFrictionOnEachSide) {
  // A contact on a joint with a law (contact_laws.h) has a friction
  // coefficient of its own, which changes from step to step: the recorded
  // contact's terms come out with the one it was factorized with (0.9), the
  // current one's with today's (0.4).
  const BlockSparseMatrix m = pattern();
  std::srand(7);
  const ContactKey key{0, 2, 1, 1};
  const std::vector<ContactSlots> slots{slots_of(m, 0, 1)};
  const std::pair<ContactState, ContactState> changes[] = {
      {ContactState::Sliding, ContactState::Sliding},  // the slip reversed
      {ContactState::Sliding, ContactState::Locked},
      {ContactState::Locked, ContactState::Sliding},
      {ContactState::Sliding, ContactState::Open}};
  for (const auto& [before, now] : changes) {
    DdaContact then = contact(key, 0, before, 1.0);
    then.law.emplace();
    then.law_friction = 0.9;
    DdaContact current = then;
    current.state = now;
    current.slip_sign = -1.0;
    current.law_friction = 0.4;
    FactoredContacts factored;
    factored.record({then}, slots);
    factored.contacts_replaced();
    LowRankUpdate terms;
    ASSERT_TRUE(factored.describe({current}, slots, kSprings, kFriction, 100, terms));
    const Eigen::MatrixXd expected = assembled({current}, slots) - assembled({then}, slots);
    EXPECT_LE((testing::dense(terms, 18) - expected).norm(), 1e-14 * expected.norm())
        << static_cast<int>(before) << " -> " << static_cast<int>(now);
  }
  // Recorded sliding, gone now: its own friction is taken out.
  DdaContact gone = contact(key, 0, ContactState::Sliding, 1.0);
  gone.law.emplace();
  gone.law_friction = 0.9;
  FactoredContacts factored;
  factored.record({gone}, slots);
  factored.contacts_replaced();
  LowRankUpdate terms;
  ASSERT_TRUE(factored.describe({}, {}, kSprings, kFriction, 100, terms));
  const Eigen::MatrixXd expected = -assembled({gone}, slots);
  EXPECT_LE((testing::dense(terms, 18) - expected).norm(), 1e-14 * expected.norm());
}

}  // namespace
}  // namespace fissure::dda

// Held contacts (mechanics/dda/open_close.h): a contact that has changed state
// kMaxStateChanges times in a step keeps the state of the last solve when that
// state violates the contact law by less than the hold tolerance, and changes
// as usual otherwise.
#include <gtest/gtest.h>

#include "mechanics/dda/open_close.h"

namespace fissure::dda {
namespace {

constexpr double kNormal = 1e10, kShear = 1e10;  // N/m
constexpr double kTolerance = 1e-3;              // N, state changes below are noise
constexpr double kHoldTolerance = 10;            // N

/// A locked contact of block 0 (six unknowns) against a fixed block, its gap
/// d = x_1 (unit normal along y) and slip ds = x_0, carrying N = 1e4 N.
struct OneContact {
  std::vector<DdaContact> contacts{1};
  std::vector<ContactSlots> slots{1};
  RockMass state;
  std::vector<double> friction{0.5};

  OneContact() {
    DdaContact& c = contacts[0];
    c.state = ContactState::Locked;
    c.e(1) = 1;
    c.es(0) = 1;
    c.gap0 = -1e-6;  // 1e4 N of compression at x = 0
    slots[0].dof_i = 0;
    state.joints.push_back(JointProperties{"joint", 0.4636, 0, 0});
  }

  /// One open-close update at the gap d and the slip ds.
  OpenCloseResult update(double gap, double slip = 0) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
    x(0) = slip;
    x(1) = gap - contacts[0].gap0;
    return update_contact_states(contacts, slots, x, {kNormal, kShear}, kTolerance, kHoldTolerance,
                                 friction, state);
  }
};

TEST(OpenCloseHold, ChatteringContactWithASmallViolationKeepsItsState) {
  OneContact f;
  f.contacts[0].state_changes = kMaxStateChanges;
  // Tension of 5 N (< 10 N): the closed state of the last solve is kept.
  const OpenCloseResult r = f.update(5e-10);
  EXPECT_EQ(r.state_changes, 0);
  EXPECT_EQ(r.held, 1);
  EXPECT_EQ(f.contacts[0].state, ContactState::Locked);
  EXPECT_NEAR(f.contacts[0].normal_force, -5.0, 1e-9);  // the spring's tension, as solved
}

TEST(OpenCloseHold, ChatteringContactWithALargeViolationStillChanges) {
  OneContact f;
  f.contacts[0].state_changes = kMaxStateChanges;
  // Tension of 50 N (> 10 N): it opens.
  const OpenCloseResult r = f.update(5e-9);
  EXPECT_EQ(r.state_changes, 1);
  EXPECT_EQ(r.held, 0);
  EXPECT_EQ(f.contacts[0].state, ContactState::Open);
  EXPECT_EQ(f.contacts[0].normal_force, 0.0);
}

TEST(OpenCloseHold, ContactBelowTheChangeLimitIsNeverHeld) {
  OneContact f;
  f.contacts[0].state_changes = kMaxStateChanges - 1;
  const OpenCloseResult r = f.update(5e-10);
  EXPECT_EQ(r.state_changes, 1);
  EXPECT_EQ(r.held, 0);
  EXPECT_EQ(f.contacts[0].state, ContactState::Open);
  EXPECT_EQ(f.contacts[0].state_changes, kMaxStateChanges);
}

TEST(OpenCloseHold, StickSlipChatterIsHeldOnlyNearTheCoulombLimit) {
  // Locked with N = 1e4 N and mu = 0.5: limit 5,000 N. A trial force
  // 8 N above the limit (beyond the 0.1 % band of 5 N) would slide; held,
  // since 8 N < 10 N. 100 N above it slides.
  for (const auto& [slip_force, held] : {std::pair{5008.0, true}, std::pair{5100.0, false}}) {
    OneContact f;
    f.contacts[0].state_changes = kMaxStateChanges;
    const OpenCloseResult r = f.update(f.contacts[0].gap0, slip_force / kShear);
    EXPECT_EQ(r.held, held ? 1 : 0) << slip_force;
    EXPECT_EQ(f.contacts[0].state, held ? ContactState::Locked : ContactState::Sliding)
        << slip_force;
  }
}

}  // namespace
}  // namespace fissure::dda

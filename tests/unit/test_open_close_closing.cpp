// A contact that closes in an open-close iterate (mechanics/dda/open_close.h)
// is classified by the return mapping, like a stuck one: it sticks when its
// trial shear force p_s ds is within the Coulomb limit and slides, in the
// direction of that force, when it is above. It used to enter stuck whatever
// its trial force (Shi), carry p_s ds far above the limit for one iterate and
// slide only in the next: the detour that made rock masses cut from DFNs and
// joint sets chatter (issue 22; docs/dda.md 2, "Closing contacts").
#include <gtest/gtest.h>

#include "mechanics/dda/open_close.h"

namespace fissure::dda {
namespace {

constexpr double kNormal = 1e10, kShear = 1e10;  // N/m
constexpr double kTolerance = 1e-3;              // N
constexpr double kHoldTolerance = 10;            // N

/// An open contact of block 0 against a fixed block: gap d = x_1 (normal
/// along y), slip ds = x_0; friction coefficient 0.5.
struct OpenContact {
  std::vector<DdaContact> contacts{1};
  std::vector<ContactSlots> slots{1};
  RockMass state;
  std::vector<double> friction{0.5};

  OpenContact() {
    DdaContact& c = contacts[0];
    c.state = ContactState::Open;
    c.e(1) = 1;
    c.es(0) = 1;
    c.gap0 = 1e-7;  // open at the start of the step
    slots[0].dof_i = 0;
    state.joints.push_back(JointProperties{"joint", 0.4636, 0, 0});
  }

  OpenCloseResult update(double gap, double slip) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(6);
    x(0) = slip;
    x(1) = gap - contacts[0].gap0;
    return update_contact_states(contacts, slots, x, {kNormal, kShear}, kTolerance, kHoldTolerance,
                                 friction, state);
  }
};

TEST(OpenCloseClosing, ContactClosingWithinTheCoulombLimitSticks) {
  // Closes with N = 1e4 N (limit 5,000 N) and a trial force of 4,000 N.
  OpenContact f;
  const OpenCloseResult r = f.update(-1e-6, 4e-7);
  EXPECT_EQ(r.state_changes, 1);
  EXPECT_EQ(f.contacts[0].state, ContactState::Locked);
  EXPECT_NEAR(f.contacts[0].normal_force, 1e4, 1e-6);
}

TEST(OpenCloseClosing, ContactClosingAboveTheCoulombLimitSlidesAtOnce) {
  // Closes with N = 1e4 N and a trial force of +-20,000 N: it slides at the
  // limit, against its slip, in this iterate (the old rule locked it with a
  // 20,000 N spring force).
  for (const double slip : {2e-6, -2e-6}) {
    OpenContact f;
    const OpenCloseResult r = f.update(-1e-6, slip);
    EXPECT_EQ(r.state_changes, 1);
    EXPECT_EQ(f.contacts[0].state, ContactState::Sliding);
    EXPECT_EQ(f.contacts[0].slip_sign, slip > 0 ? 1 : -1);
    EXPECT_NEAR(f.contacts[0].shear_force, f.contacts[0].slip_sign * 5e3, 1e-6);
    // The next iterate at the same gap and slip confirms the state.
    EXPECT_EQ(f.update(-1e-6, slip).state_changes, 0);
  }
}

TEST(OpenCloseClosing, FrictionlessContactClosesSliding) {
  // Without friction no closing contact can stick: it used to enter locked
  // and carry p_s ds for one iterate.
  OpenContact f;
  f.friction = {0.0};
  f.update(-1e-6, 1e-9);
  EXPECT_EQ(f.contacts[0].state, ContactState::Sliding);
  EXPECT_EQ(f.contacts[0].shear_force, 0.0);
}

}  // namespace
}  // namespace fissure::dda

// PetscOptionsLease (core/linear/petsc_options.h): a solver's options stay
// in PETSc's process-wide database only while a solver holds them, an
// earlier setting (the environment's) wins and stays, and two solvers of one
// prefix share the first one's until the last goes.
#ifdef FISSURE_WITH_PETSC
#include <gtest/gtest.h>
#include <petscsys.h>

#include <optional>
#include <string>

#include "core/linear/petsc_options.h"
#include "core/linear/petsc_session.h"

namespace fissure {
namespace {

/// The database's value of `name`; nullopt when it is not set.
std::optional<std::string> value_of(const char* name) {
  char text[256] = {0};
  PetscBool set = PETSC_FALSE;
  EXPECT_EQ(PetscOptionsGetString(nullptr, nullptr, name, text, sizeof text, &set), 0);
  if (!set) return std::nullopt;
  return std::string(text);
}

TEST(PetscOptionsLease, TheOptionsLeaveWithTheLease) {
  ensure_petsc_initialized();
  {
    PetscOptionsLease lease;
    lease.add("-lease_a_ksp_type gmres -lease_a_ksp_max_it 7 -lease_a_shift -1 -lease_a_monitor");
    EXPECT_EQ(value_of("-lease_a_ksp_type"), "gmres");
    EXPECT_EQ(value_of("-lease_a_ksp_max_it"), "7");
    EXPECT_EQ(value_of("-lease_a_shift"), "-1");  // a value, not a name
    EXPECT_TRUE(value_of("-lease_a_monitor").has_value());
    lease.add("-lease_a_ksp_type cg");  // the defaults after the scene's: the scene's stays
    EXPECT_EQ(value_of("-lease_a_ksp_type"), "gmres");
  }
  // The next scene's solver of the same prefix starts from its own options.
  EXPECT_FALSE(value_of("-lease_a_ksp_type"));
  EXPECT_FALSE(value_of("-lease_a_ksp_max_it"));
  EXPECT_FALSE(value_of("-lease_a_shift"));
  EXPECT_FALSE(value_of("-lease_a_monitor"));
}

TEST(PetscOptionsLease, AnEarlierSettingWinsAndStays) {
  ensure_petsc_initialized();
  // As PETSC_OPTIONS would have set it when PETSc started.
  ASSERT_EQ(PetscOptionsSetValue(nullptr, "-lease_b_pc_type", "jacobi"), 0);
  {
    PetscOptionsLease lease;
    lease.add("-lease_b_pc_type hypre");
    EXPECT_EQ(value_of("-lease_b_pc_type"), "jacobi");
  }
  EXPECT_EQ(value_of("-lease_b_pc_type"), "jacobi");
  ASSERT_EQ(PetscOptionsClearValue(nullptr, "-lease_b_pc_type"), 0);
}

TEST(PetscOptionsLease, TwoLiveLeasesShareTheFirstOnesUntilTheLastGoes) {
  ensure_petsc_initialized();
  std::optional<PetscOptionsLease> first(std::in_place), second(std::in_place);
  first->add("-lease_c_ksp_type gmres");
  second->add("-lease_c_ksp_type bcgs");
  EXPECT_EQ(value_of("-lease_c_ksp_type"), "gmres");
  first.reset();  // the second solver still reads it (a new step size sets it up again)
  EXPECT_EQ(value_of("-lease_c_ksp_type"), "gmres");
  second.reset();
  EXPECT_FALSE(value_of("-lease_c_ksp_type"));
}

}  // namespace
}  // namespace fissure
#endif

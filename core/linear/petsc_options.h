// A solver's options in PETSc's options database, for the solver's lifetime.
// The database is the process's: options a scene's solver put there would
// otherwise reach every later solver of that prefix, such as the next
// scene's in a process that runs several (a test program, a study). The
// environment's PETSC_OPTIONS and the command line, set before, win and stay.
#pragma once

#ifdef FISSURE_WITH_PETSC
#include <string>
#include <vector>

namespace fissure {

/// Whether `token` of an options string names an option ("-ksp_type"), not
/// a value: "-1" and "-.5" are values.
bool is_petsc_option_name(const std::string& token);

class PetscOptionsLease {
 public:
  PetscOptionsLease() = default;
  PetscOptionsLease(const PetscOptionsLease&) = delete;
  PetscOptionsLease& operator=(const PetscOptionsLease&) = delete;
  /// Clears the options this lease holds that no other live lease holds.
  ~PetscOptionsLease();

  /// Sets each option of `options` ("-name [value] ...", prefixed) unless
  /// the database has it already: the earlier setting wins (the
  /// environment's, the command line's, an earlier call's, or another live
  /// solver's of the same prefix, which this one then shares).
  void add(const std::string& options);

 private:
  std::vector<std::string> held_;  ///< names this lease set or shares
};

}  // namespace fissure
#endif

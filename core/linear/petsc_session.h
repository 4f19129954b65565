// PETSc lifetime and error discipline: PETSc is initialised on
// first use only (a scene that never uses it pays nothing), finalised at exit,
// and every call goes through FISSURE_PETSC_CALL, which turns an error code
// into a SolverError instead of PETSc's default abort/traceback.
#pragma once

#ifdef FISSURE_WITH_PETSC
#include <petscsys.h>

#include <string>

#include "core/base/errors.h"

namespace fissure {

/// Initialises PETSc once per process (thread-unsafe; call from the main thread).
void ensure_petsc_initialized();

/// Options of a scene with a solver's prefix, for PetscOptionsInsertString:
/// ("-ksp_type cg -pc_type hypre", "a_") -> "-a_ksp_type cg -a_pc_type
/// hypre"; values such as "-1" or "-.5" are kept.
std::string petsc_options_with_prefix(const std::string& options, const std::string& prefix);

}  // namespace fissure

#define FISSURE_PETSC_CALL(call)                                         \
  do {                                                                   \
    const PetscErrorCode fissure_petsc_ierr = (call);                    \
    FISSURE_CHECK(fissure_petsc_ierr == 0, ::fissure::SolverError,       \
                  "PETSc error " << fissure_petsc_ierr << " in " #call); \
  } while (false)

#endif

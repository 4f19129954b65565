// PETSc lifetime and error discipline: PETSc is initialised on
// first use only (a scene that never uses it pays nothing), finalised at exit,
// and every call goes through FISSURE_PETSC_CALL, which turns an error code
// into a SolverError instead of PETSc's default abort/traceback.
#pragma once

#ifdef FISSURE_WITH_PETSC
#include <petscsys.h>

#include <string>

#include "core/base/errors.h"
#include "core/linear/linear_solver_controls.h"

namespace fissure {

/// Initialises PETSc once per process (thread-unsafe; call from the main thread).
void ensure_petsc_initialized();

/// Options of a scene with a solver's prefix, for PetscOptionsInsertString:
/// ("-ksp_type cg -pc_type hypre", "a_") -> "-a_ksp_type cg -a_pc_type
/// hypre"; values such as "-1" or "-.5" are kept.
std::string petsc_options_with_prefix(const std::string& options, const std::string& prefix);

/// PETSc's own words for the last error on this thread ("Unknown KSP type:
/// nonsense"), recorded by the error handler ensure_petsc_initialized()
/// installs; else the text of `code`.
std::string petsc_error_text(PetscErrorCode code);

/// Throws for a PETSc call that applies the scene's options of `controls`
/// (KSPSetFromOptions, KSPSetUp): the message names the options and their
/// scene line, as a scene error would.
void check_scene_options_call(PetscErrorCode code, const char* call,
                              const LinearSolverControls& controls);

}  // namespace fissure

#define FISSURE_PETSC_CALL(call)                                                      \
  do {                                                                                \
    const PetscErrorCode fissure_petsc_ierr = (call);                                 \
    FISSURE_CHECK(fissure_petsc_ierr == 0, ::fissure::SolverError,                    \
                  "PETSc error " << fissure_petsc_ierr << " in " #call << ": "        \
                                 << ::fissure::petsc_error_text(fissure_petsc_ierr)); \
  } while (false)

#endif

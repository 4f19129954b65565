#include "core/linear/petsc_session.h"

#ifdef FISSURE_WITH_PETSC
#include <cstdlib>

namespace fissure {

void ensure_petsc_initialized() {
  PetscBool initialized = PETSC_FALSE;
  PetscInitialized(&initialized);
  if (initialized) return;
  FISSURE_CHECK(PetscInitializeNoArguments() == 0, SolverError, "PETSc could not be initialised");
  // Errors come back as codes (turned into exceptions), not as aborts.
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  std::atexit([] { PetscFinalize(); });
}

}  // namespace fissure
#endif

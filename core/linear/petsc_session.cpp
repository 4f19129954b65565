#include "core/linear/petsc_session.h"

#ifdef FISSURE_WITH_PETSC
#include <cctype>
#include <cstdlib>
#include <sstream>

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

std::string petsc_options_with_prefix(const std::string& options, const std::string& prefix) {
  std::istringstream in(options);
  std::ostringstream out;
  std::string token;
  while (in >> token) {
    const bool option = token.size() > 1 && token[0] == '-' &&
                        !std::isdigit(static_cast<unsigned char>(token[1])) && token[1] != '.';
    out << (option ? "-" + prefix + token.substr(1) : token) << ' ';
  }
  return out.str();
}

}  // namespace fissure
#endif

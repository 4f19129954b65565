#include "core/linear/petsc_session.h"

#ifdef FISSURE_WITH_PETSC
#include <cstdlib>
#include <sstream>

#include "core/linear/petsc_options.h"

namespace fissure {

namespace {

thread_local std::string last_error;

/// Records PETSc's message where the error arose, and returns the code (no
/// abort, no traceback: the caller throws).
PetscErrorCode record_error(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) last_error = message ? message : "";
  return code;
}

}  // namespace

std::string petsc_error_text(PetscErrorCode code) {
  std::string text = last_error;
  last_error.clear();
  if (text.empty()) {
    const char* generic = nullptr;
    PetscErrorMessage(code, &generic, nullptr);
    text = generic ? generic : "";
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  // One line: a message is a line of a located report (PETSc continues some
  // on an indented second line: "... initial guess\n  you probably want").
  std::string line;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') {
      line += text[i];
      continue;
    }
    while (i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\n')) ++i;
    line += "; ";
  }
  return line;
}

void check_scene_options_call(PetscErrorCode code, const char* call,
                              const LinearSolverControls& controls) {
  if (code == 0) return;
  const std::string reason = petsc_error_text(code);
  FISSURE_CHECK(controls.petsc_options.empty(), SceneError,
                controls.petsc_options_location
                    << ": found petsc_options \"" << controls.petsc_options
                    << "\", which PETSc refuses (" << reason << ", in " << call
                    << "); expected options PETSc's KSP and PC know (their list: the PETSc "
                       "manual, or -help in PETSC_OPTIONS)");
  FISSURE_CHECK(false, SolverError, "PETSc error " << code << " in " << call << ": " << reason);
}

void ensure_petsc_initialized() {
  PetscBool initialized = PETSC_FALSE;
  PetscInitialized(&initialized);
  if (initialized) return;
  FISSURE_CHECK(PetscInitializeNoArguments() == 0, SolverError, "PETSc could not be initialised");
  // Errors come back as codes (turned into exceptions), not as aborts.
  PetscPushErrorHandler(record_error, nullptr);
  std::atexit([] { PetscFinalize(); });
}

std::string petsc_options_with_prefix(const std::string& options, const std::string& prefix) {
  std::istringstream in(options);
  std::ostringstream out;
  std::string token;
  while (in >> token) {
    out << (is_petsc_option_name(token) ? "-" + prefix + token.substr(1) : token) << ' ';
  }
  return out.str();
}

}  // namespace fissure
#endif

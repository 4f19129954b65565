// Typed exceptions and the two levels of checks (deal.II's Assert/AssertThrow,
// MFEM's MFEM_ASSERT/MFEM_VERIFY):
//  * FISSURE_ASSERT(cond)            programming errors, debug builds only;
//  * FISSURE_CHECK(cond, Exc, msg)   run-time failures, always on, throws Exc
//                                    with a streamed message.
#pragma once

#include <cassert>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fissure {

/// Base of every error Fissure reports to the user.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Invalid scene input (the scene parser collects and reports all of them).
class SceneError : public Error {
 public:
  using Error::Error;
};

/// A process that finds at its first step that coupling.order runs it
/// before a process it depends on (a block region before the continuum it
/// is tied to): the coordinator adds where the order is written.
class CouplingOrderError : public SceneError {
 public:
  using SceneError::SceneError;
};

/// Invalid or degenerate geometry (polygons, fractures).
class GeometryError : public Error {
 public:
  using Error::Error;
};

/// A linear or nonlinear solver failed.
class SolverError : public Error {
 public:
  using Error::Error;
};

/// A run diverged: NaN, or a step that no time-step cut can rescue.
class DivergenceError : public Error {
 public:
  using Error::Error;
};

/// Reading or writing files failed.
class IoError : public Error {
 public:
  using Error::Error;
};

}  // namespace fissure

#define FISSURE_CHECK(cond, ExcType, msg)    \
  do {                                       \
    if (!(cond)) {                           \
      std::ostringstream fissure_check_os;   \
      fissure_check_os << msg;               \
      throw ExcType(fissure_check_os.str()); \
    }                                        \
  } while (false)

#define FISSURE_ASSERT(cond) assert(cond)

#include "flow/network/fluid.h"

#include <cmath>

#include "core/base/errors.h"

namespace fissure::flow {

void check_fluid(const FluidProperties& f) {
  FISSURE_CHECK(std::isfinite(f.viscosity) && f.viscosity > 0, SceneError,
                "flow: fluid viscosity is " << f.viscosity << " Pa s; expected a viscosity > 0");
  FISSURE_CHECK(std::isfinite(f.density) && f.density >= 0, SceneError,
                "flow: fluid density is " << f.density << " kg/m^3; expected a density >= 0");
  FISSURE_CHECK(std::isfinite(f.bulk_modulus) && f.bulk_modulus > 0, SceneError,
                "flow: fluid bulk modulus is " << f.bulk_modulus << " Pa; expected a modulus > 0");
}

}  // namespace fissure::flow

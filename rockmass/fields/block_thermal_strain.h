// The blocks' free thermal strain, as the shared field "block_thermal_strain"
// (written by the thermal process, which owns the materials' linear thermal
// expansion; read by the mechanics for the thermal stress of theory.md 4.3).
#pragma once

#include <vector>

#include "core/base/named_values.h"

namespace fissure {

/// Per block (index of RockMass::blocks): the isotropic free (stress-free)
/// linear strain alpha_T dT of the block, dT its mean temperature minus its
/// stress-free reference temperature (dimensionless). Absent: no thermal
/// strain.
inline constexpr Key<std::vector<double>> kBlockThermalStrain{"block_thermal_strain"};

}  // namespace fissure

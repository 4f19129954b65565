// Reading the fluid's properties (FluidProperties) from a `fluid` map: the
// scene's flow.fluid and a REV study's fluid, with the same keys, units and
// ranges, and the defaults of FluidProperties.
#pragma once

#include <span>
#include <string_view>

#include "core/scene/config_map.h"
#include "rockmass/physical_quantities.h"
#include "flow/network/fluid.h"

namespace fissure {


namespace flow {

/// The keys of a `fluid` map: density, viscosity, bulk_modulus.
extern const std::span<const std::string_view> kFluidKeys;

/// Reads `node` (a map with kFluidKeys, documented under `table.section`)
/// into `fluid`, keeping the defaults it holds.
void read_fluid(const ConfigNode& node, const KeyTable& table, FluidProperties& fluid);

}  // namespace flow
}  // namespace fissure

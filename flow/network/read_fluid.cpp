#include "flow/network/read_fluid.h"

namespace fissure::flow {

namespace {
constexpr std::string_view kKeys[] = {"density", "viscosity", "bulk_modulus"};
}  // namespace

const std::span<const std::string_view> kFluidKeys{kKeys};

void read_fluid(const ConfigNode& node, const KeyTable& table, FluidProperties& fluid) {
  ConfigMap map(node, table);
  map.read("density", fluid.density, quantity::density, Range::positive());
  map.read("viscosity", fluid.viscosity, quantity::viscosity, Range::positive());
  map.read("bulk_modulus", fluid.bulk_modulus, quantity::pressure, Range::positive());
}

}  // namespace fissure::flow

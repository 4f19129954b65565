#include "rockmass/heat_keys.h"

namespace fissure::heat_keys {

Range temperature_range() {
  return Range::open(kAbsoluteZeroCelsius, 1e4);
}

void read_heat_transfer(const ConfigNode& node, const KeyTable& table, double& coefficient,
                        double& temperature) {
  ConfigMap map(node, table);
  map.read_required("coefficient", coefficient, quantity::transfer_coefficient,
                    Range::non_negative());
  map.read_required("temperature", temperature, quantity::temperature, temperature_range());
}

}  // namespace fissure::heat_keys

// The blocks' temperature change, as the shared field
// "block_temperature_change" (written by the thermal process, read by the
// mechanics for the thermal strain of theory.md 4.3).
#pragma once

#include <vector>

#include "core/base/named_values.h"

namespace fissure {

/// Per block (index of RockMass::blocks): the block's mean temperature minus
/// its stress-free reference temperature (K). Absent: no thermal strain.
inline constexpr Key<std::vector<double>> kBlockTemperatureChange{"block_temperature_change"};

}  // namespace fissure

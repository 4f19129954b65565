// Where the blocks' state holds a value that is not a finite number (issue
// 22, item 4): the coordinator checks every accepted step with it and
// retries the step smaller or stops with the diagnosis, so that no nan or
// inf reaches the output files. The processes check the fields they own
// (the flow its pressures) before they commit a step.
#pragma once

#include <string>

#include "core/state/rock_mass.h"

namespace fissure {

/// "block 'b7' (7) has a non-finite velocity" for the first block whose
/// vertices, velocity, stress, strain or rotation are not finite; "" if none.
std::string non_finite_block(const RockMass& state);

}  // namespace fissure

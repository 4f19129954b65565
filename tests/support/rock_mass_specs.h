// Rock masses shared by the block-cutting tests and the block_cutting
// benchmark, built directly as RockMassSpec values.
#pragma once

#include <cstdint>

#include "rockmass/rock_mass_spec.h"

namespace fissure::testing {

/// A random DFN at fixed density: two families (P20 = 1 per m^2 each,
/// exponential trace lengths of mean 2 m, apertures 0.1 mm; one von Mises
/// around 30 deg with kappa = 10, one uniform) in an L x L box with a
/// 48-sided tunnel of radius 0.1 L centred at (0.5 L, 0.4 L). L is chosen so
/// that `n` fractures are expected to be drawn (dfn_generator.h: n = P20 (L^2
/// + 2 L E[l] + E[l^2])): the domain grows with n, the density does not.
/// Merge tolerance 1e-5 L, max_blocks 1e7.
RockMassSpec random_dfn_spec(int n, std::uint64_t seed);

}  // namespace fissure::testing

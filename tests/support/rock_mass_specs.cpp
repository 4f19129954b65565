#include "tests/support/rock_mass_specs.h"

#include <cmath>
#include <numbers>

#include "core/geometry/domain_sides.h"

namespace fissure::testing {

RockMassSpec random_dfn_spec(int n, std::uint64_t seed) {
  const double p20 = 2.0, mean_length = 2.0;
  const double el2 = 2 * mean_length * mean_length;  // exponential: E[l^2] = 2 E[l]^2
  const double L = -mean_length + std::sqrt(mean_length * mean_length - el2 + n / p20);
  RockMassSpec spec;
  spec.domain = {{0, 0}, {L, 0}, {L, L}, {0, L}};
  spec.excavations.push_back(
      ExcavationSpec{"tunnel", regular_polygon(Vec2(0.5 * L, 0.4 * L), 0.1 * L, 48)});
  spec.seed = seed;
  spec.merge_tolerance = 1e-5 * L;
  spec.max_blocks = 10000000;
  spec.max_fractures = 10000000;

  DfnFamilySpec a;
  a.name = "a";
  a.density_kind = DfnFamilySpec::Density::P20;
  a.density = 0.5 * p20;
  a.orientation.type = DistributionSpec::Type::VonMises;
  a.orientation.mean = 30 * std::numbers::pi / 180;
  a.orientation.kappa = 10;
  a.length.type = DistributionSpec::Type::Exponential;
  a.length.mean = mean_length;
  a.aperture.value = 1e-4;
  DfnFamilySpec b = a;
  b.name = "b";
  b.orientation.type = DistributionSpec::Type::Uniform;
  spec.dfn = {a, b};
  return spec;
}

}  // namespace fissure::testing

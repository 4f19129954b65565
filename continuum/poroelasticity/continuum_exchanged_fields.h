// The continuum's values that the others read, as the iterated scheme tests
// and relaxes them (SectionReader::exchanges, Process::exchanged_values):
// what it returns on its interfaces (`continuum_interfaces`), the
// displacements (at the nodes and the edges' midpoints), the pressures, the
// temperatures, the fluid fluxes and the heat fluxes.
#pragma once

#include "core/scene/exchanged_field.h"
#include "rockmass/physical_quantities.h"

namespace fissure::continuum {

enum ExchangedContinuumField : std::size_t {
  kDisplacement,
  kPressure,
  kTemperature,
  kFluidFlux,
  kHeatFlux
};

inline constexpr ExchangedFieldKind kExchangedFields[] = {
    {"continuum_interfaces.displacement", &quantity::length},
    {"continuum_interfaces.pressure", &quantity::stress},
    {"continuum_interfaces.temperature", &quantity::temperature},
    {"continuum_interfaces.fluid_flux", &quantity::velocity},
    {"continuum_interfaces.heat_flux", &quantity::heat_flux},
};

}  // namespace fissure::continuum

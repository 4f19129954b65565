// The fields a process gives the others in the iterated staggered scheme
// (coupling.scheme: iterated; docs/architecture.md 5), declared by name and
// kind of quantity in its section (SectionReader::exchanges), so that
// coupling.iteration.fields can give each its own tolerances in its own unit
// and the framework tests each against them without knowing what it is.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/scene/units.h"

namespace fissure {

struct Scene;

struct ExchangedFieldKind {
  std::string_view name;  ///< "pressure_loads", "fracture_flow.aperture"
  /// The kind of its changes, the unit of its absolute tolerance (a
  /// temperature difference for a temperature).
  const QuantityKind* quantity;
};

/// The default absolute tolerance (SI) of a field of `kind`: a change below
/// it is round-off for any scene of rock (a millipascal, a picometre, a
/// microkelvin, ...), so that a field that is (nearly) zero converges. Per
/// dimension; a logic_error for a dimension without one (a developer who
/// declares a field of a new kind adds its default here).
double default_absolute_tolerance(const QuantityKind& kind);

/// The exchanged field `name` of a process that `scene` switches on, or null.
const ExchangedFieldKind* exchanged_field(const Scene& scene, std::string_view name);

/// The names of every exchanged field of the processes `scene` switches on,
/// comma-separated, for messages.
std::string exchanged_field_names(const Scene& scene);

}  // namespace fissure

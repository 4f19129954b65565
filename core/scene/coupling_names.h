// The names of the coupling's choices (docs/scene-reference.md section 8),
// one table each, for the reader and for summary.json.
#pragma once

#include "core/base/enum_names.h"
#include "core/scene/scene.h"

namespace fissure {

inline constexpr EnumName<CouplingSettings::Scheme> kSchemeNames[] = {
    {"lie", CouplingSettings::Scheme::Lie},
    {"strang", CouplingSettings::Scheme::Strang},
    {"iterated", CouplingSettings::Scheme::Iterated}};
inline constexpr EnumName<CouplingSettings::Iteration::Relaxation> kRelaxationNames[] = {
    {"aitken", CouplingSettings::Iteration::Relaxation::Aitken},
    {"fixed", CouplingSettings::Iteration::Relaxation::Fixed},
    {"quasi_newton", CouplingSettings::Iteration::Relaxation::QuasiNewton}};

}  // namespace fissure

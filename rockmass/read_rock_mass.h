// Internal to core/scene: reading the items of the `rock_mass` section that
// have a file of their own (joint sets and DFN families,
// read_rock_mass_sets.cpp), for read_rock_mass.cpp; a DFN family on its own is
// read by the REV study too (coupling/rev_sources.cpp).
#pragma once

#include "core/scene/scene_draft.h"

namespace fissure {

namespace quantity {
/// Fracture densities (docs/rock-mass.md): P20 per area, P21 length per area.
inline constexpr QuantityKind areal_density{
    "number per area", {0, -2, 0, 0, 0}, "1/m^2, 1/km^2", "1/m^2", 1};
inline constexpr QuantityKind fracture_intensity{
    "length per area", {0, -1, 0, 0, 0}, "1/m, m/m^2", "1/m", 1};
}  // namespace quantity

/// Reads one item of `rock_mass.joint_sets`; its name goes into `sets`.
JointSetSpec read_joint_set(const ConfigNode& node, SceneDraft& draft, NameRegistry& sets);

/// Reads one item of `rock_mass.dfn`; its name goes into `sets`.
DfnFamilySpec read_dfn_family(const ConfigNode& node, SceneDraft& draft, NameRegistry& sets);
/// Reads a DFN family with the keys of a `rock_mass.dfn` item outside a scene
/// (the REV study's `network.dfn.families[]`, coupling/rev_sources.cpp): there
/// are no joints, so a `joint` key is reported. Its name goes into `families`.
DfnFamilySpec read_dfn_family(const ConfigNode& node, NameRegistry& families);

/// Default hydraulic aperture of generated fractures (docs/rock-mass.md).
inline constexpr double kDefaultAperture = 1e-4;  // m

}  // namespace fissure

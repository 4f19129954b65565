// The scene's `rock_mass` section (docs/scene-reference.md section 5,
// docs/rock-mass.md): read and checked into a RockMassSpec (read_rock_mass.cpp,
// read_rock_mass_sets.cpp), then generated into blocks and the fracture graph
// (generate_rock_mass.h) once every section is read. A DFN family on its own
// is read by the REV study too (flow/rev/rev_dfn_source.cpp).
#pragma once

#include "core/scene/scene_section.h"
#include "rockmass/rock_mass_spec.h"

namespace fissure {

namespace quantity {
/// Fracture densities (docs/rock-mass.md): P20 per area, P21 length per area.
inline constexpr QuantityKind areal_density{
    "number per area", {0, -2, 0, 0, 0}, "1/m^2, 1/km^2", "1/m^2", 1, 1e12};
inline constexpr QuantityKind fracture_intensity{
    "length per area", {0, -1, 0, 0, 0}, "1/m, m/m^2", "1/m", 1, 1e6};
}  // namespace quantity

/// The reader and generator of the section (the registry's block source).
extern const SectionReader kRockMassSection;

/// The keys of the section's maps (docs test, and the REV study's DFN).
namespace rock_mass_keys {
extern const KeyTable rock_mass;        ///< rock_mass
extern const KeyTable excavation;       ///< rock_mass.excavations[]
extern const KeyTable circle;           ///< rock_mass.excavations[].circle
extern const KeyTable joint_set;        ///< rock_mass.joint_sets[]
extern const KeyTable dfn_family;       ///< rock_mass.dfn[]
extern const KeyTable dfn_density;      ///< rock_mass.dfn[].density
extern const KeyTable dfn_orientation;  ///< rock_mass.dfn[].orientation
extern const KeyTable dfn_length;       ///< rock_mass.dfn[].length
extern const KeyTable dfn_aperture;     ///< rock_mass.dfn[].aperture
extern const KeyTable fracture;         ///< rock_mass.fractures[]
extern const KeyTable fixed_blocks;     ///< rock_mass.fixed_blocks
}  // namespace rock_mass_keys

/// Reads one item of `rock_mass.joint_sets`, resolving its joint in
/// `joints`; its name goes into `sets`.
JointSetSpec read_joint_set(const ConfigNode& node, const NameRegistry& joints, NameRegistry& sets);

/// Reads one item of `rock_mass.dfn`; its name goes into `sets`.
DfnFamilySpec read_dfn_family(const ConfigNode& node, const NameRegistry& joints,
                              NameRegistry& sets);
/// Reads a DFN family with the keys of a `rock_mass.dfn` item outside a scene
/// (the REV study's `network.dfn.families[]`, flow/rev/rev_dfn_source.cpp): there
/// are no joints, so a `joint` key is reported. Its name goes into `families`.
DfnFamilySpec read_dfn_family(const ConfigNode& node, NameRegistry& families);

/// Default hydraulic aperture of generated fractures (docs/rock-mass.md).
inline constexpr double kDefaultAperture = 1e-4;  // m
/// Hydraulic apertures: at most 10 cm. Beyond, the opening is no fracture
/// for the cubic law (the flow is turbulent, the blocks are apart), and an
/// aperture typed without its unit ('40' for 40 um, read as 40 m) made the
/// network's conductances span 30 orders of magnitude (fuzz case 7609).
inline constexpr double kMaxAperture = 0.1;  // m
inline Range aperture_range() {
  return Range::open_closed(0, kMaxAperture);
}
/// Log-normal apertures: the largest coefficient of variation std / mean
/// (read_rock_mass_sets.cpp gives the reason).
inline constexpr double kMaxApertureVariation = 10;

}  // namespace fissure

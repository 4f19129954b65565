// The near-field / far-field coupling boundary of the continuum
// (docs/continuum.md 4, "Interfaces"; theory.md 6), as two shared fields,
// each with one writer:
//  * "continuum_interfaces", written by the continuum: per interface, a
//    named boundary of the continuum, its nodes and the values the
//    continuum gives back after each step (displacements, fluxes out of
//    it); made at initialize;
//  * "continuum_interface_loads", written by the process on the other side:
//    per interface, the values it gives the continuum there (tractions,
//    pressures, temperatures) before the continuum advances, per node of
//    the interface's `nodes`.
#pragma once

#include <string>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

/// What the continuum publishes on an interface.
struct ContinuumInterface {
  /// The continuum boundary's name (continuum.conditions[].boundary).
  std::string name;
  /// The boundary's mesh vertices, m, in the continuum's fixed order (as
  /// the boundary's edges meet them). Every per-node vector has this
  /// length, or is empty; so have those of its ContinuumInterfaceLoad.
  std::vector<Vec2> nodes;
  /// Displacement from the initial state, m.
  std::vector<Vec2> displacement;
  /// Fluid flux out of the continuum, normal to the boundary, m^3/s per m^2
  /// (m/s): the consistent reaction of the flow equation at a node whose
  /// pressure is given, over the node's share of the boundary; 0 where not.
  std::vector<double> fluid_flux;
  /// Heat flux out of the continuum, normal to the boundary, W/m^2: the
  /// consistent reaction of the heat equation where the temperature is
  /// given; 0 where not.
  std::vector<double> heat_flux;
};

/// What another process gives the continuum on an interface; an empty
/// vector: not given in this step.
struct ContinuumInterfaceLoad {
  /// The interface's name (its ContinuumInterface's).
  std::string name;
  /// Traction vector per node, Pa (the force per unit area the other side
  /// exerts on the continuum), linear between the nodes.
  std::vector<Vec2> traction;
  /// Fluid pressure per node, Pa (absolute, as the continuum's pressure).
  std::vector<double> pressure;
  /// Temperature per node, degC.
  std::vector<double> temperature;
};

/// Absent: the scene has no continuum interface.
inline constexpr Key<std::vector<ContinuumInterface>> kContinuumInterfaces{"continuum_interfaces"};
/// Absent or without an interface's entry: nothing given there.
inline constexpr Key<std::vector<ContinuumInterfaceLoad>> kContinuumInterfaceLoads{
    "continuum_interface_loads"};

/// The entry of that name; null when there is none.
template <class Entry>
Entry* find_interface(std::vector<Entry>& all, const std::string& name) {
  for (Entry& i : all)
    if (i.name == name) return &i;
  return nullptr;
}

}  // namespace fissure

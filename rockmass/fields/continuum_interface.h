// The near-field / far-field coupling boundary of the continuum, as the
// shared field "continuum_interfaces" (docs/continuum.md 4, "Interfaces";
// theory.md 6): per interface, a named boundary of the continuum, its
// nodes, the values another process gives the continuum there (tractions,
// pressures, temperatures) and the values the continuum gives back after
// each step (displacements, fluxes out of it). The continuum makes the
// interfaces at initialize; another process fills in the given values
// before the continuum advances and reads the returned ones after.
#pragma once

#include <string>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

struct ContinuumInterface {
  /// The continuum boundary's name (continuum.conditions[].boundary).
  std::string name;
  /// The boundary's mesh vertices, m, in the continuum's fixed order (as
  /// the boundary's edges meet them). Every per-node vector below has this
  /// length, or is empty.
  std::vector<Vec2> nodes;

  // Given TO the continuum by another process; empty: not given.
  /// Traction vector per node, Pa (the force per unit area the other side
  /// exerts on the continuum), linear between the nodes.
  std::vector<Vec2> traction;
  /// Fluid pressure per node, Pa (absolute, as the continuum's pressure).
  std::vector<double> pressure;
  /// Temperature per node, degC.
  std::vector<double> temperature;

  // Given BACK by the continuum after each step (one per node).
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

/// Absent: the scene has no continuum interface.
inline constexpr Key<std::vector<ContinuumInterface>> kContinuumInterfaces{"continuum_interfaces"};

/// The interface of that name; null when there is none.
inline ContinuumInterface* find_interface(std::vector<ContinuumInterface>& all,
                                          const std::string& name) {
  for (ContinuumInterface& i : all)
    if (i.name == name) return &i;
  return nullptr;
}

}  // namespace fissure

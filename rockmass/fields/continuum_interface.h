// The near-field / far-field coupling boundary of the continuum
// (docs/continuum.md 4, "Interfaces"; docs/architecture.md 5, "A discrete
// region inside the continuum"), as two shared fields:
//  * "continuum_interfaces", written by the continuum alone: per interface,
//    a named boundary of the continuum, its nodes and edges, what it takes,
//    and the values it gives back after each step (its trace: displacements,
//    pressures, temperatures; the fluxes out of it); made at initialize;
//  * "continuum_interface_loads", written by the processes on the other
//    side, each its own member: per interface, what they give the continuum
//    before it advances: tractions (per node, or on pieces of its edges: a
//    block region's, rockmass/fields/interface_ties.h), pressures, temperatures, or inflows
//    at points of their own along the interface (a fracture network's mouths).
//
// Inflows at points are applied by the continuum with its own shape
// functions at the point (f_i += N_i(x) Q), and the trace it gives back is
// sampled at the point with the same functions (p(x) = N_i(x) p_i): the
// load transfer is the transpose of the trace transfer, so that the fluid's
// mass is conserved exactly (Farhat, Lesoinne and Le Tallec 1998).
// Both sides place a point on the interface with locate_on_interface, so
// that they agree on N_i(x).
#pragma once

#include <array>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/base/named_values.h"
#include "core/geometry/vec2.h"

namespace fissure {

/// What the continuum publishes on an interface.
struct ContinuumInterface {
  /// The continuum boundary's name (continuum.conditions[].boundary).
  std::string name;
  /// The boundary's mesh vertices, m, in the continuum's fixed order. Every
  /// per-node vector has this length, or is empty; so have those of its
  /// ContinuumInterfaceLoad.
  std::vector<Vec2> nodes;
  /// The boundary's element edges, as indices into `nodes`; straight, with
  /// the displacement's quadratic (P2) node at the midpoint.
  std::vector<std::array<int, 2>> edges;
  /// What the continuum takes there (its condition's `interface` list):
  /// tractions; pressures; fluid flows at points; temperatures; heat fluxes
  /// on pieces.
  struct Takes {
    bool traction = false, pressure = false, fluid_flow = false, temperature = false,
         heat_flow = false;
  } takes;
  /// The continuum's stiffness and conductances seen from the interface, per
  /// unit length of it: the other side's Robin coefficients (its loads
  /// follow its values' differences from the trace at these rates; the
  /// choice that makes the iteration contract fastest, docs/architecture.md
  /// 5, "A discrete region inside the continuum"). Those of a hole of the
  /// interface's perimeter in an infinite plane: 2G/R (Pa/m) under an even
  /// pressure, k/(mu R) (m/(Pa s)) and lambda/R (W/(m^2 K)) for steady flow,
  /// R = perimeter / (2 pi), with the rock beside the interface.
  struct Impedance {
    double stiffness = 0, fluid = 0, heat = 0;
  } impedance;
  /// Displacement from the initial state, m, per node and at each edge's
  /// midpoint (per edge of `edges`).
  std::vector<Vec2> displacement;
  std::vector<Vec2> midside_displacement;
  /// Pore pressure (Pa, absolute) and temperature (degC) per node, linear
  /// along each edge; temperature empty when the continuum solves no heat.
  std::vector<double> pressure;
  std::vector<double> temperature;
  /// Fluid flux out of the continuum, normal to the boundary, m^3/s per m^2
  /// (m/s): the consistent reaction of the flow equation at a node whose
  /// pressure is given, over the node's share of the boundary; 0 where not.
  std::vector<double> fluid_flux;
  /// Heat flux out of the continuum, normal to the boundary, W/m^2: the
  /// consistent reaction of the heat equation where the temperature is
  /// given; 0 where not.
  std::vector<double> heat_flux;
};

/// Loads at points along an interface, per unit thickness: `values[i]` at
/// `points[i]` (m, on the interface; placed with locate_on_interface).
template <class T>
struct InterfacePointLoads {
  std::vector<Vec2> points;
  std::vector<T> values;
  bool empty() const { return points.empty(); }
};

/// A value on a piece [s0, s1] of an interface edge (s along the edge from
/// its first node): t0 at s0, t1 at s1, linear between.
template <class T>
struct InterfacePiece {
  int edge = -1;
  double s0 = 0, s1 = 1;
  T t0{}, t1{};
};
/// A traction on a piece, Pa (on the continuum).
using TractionPiece = InterfacePiece<Vec2>;
/// A heat flux into the continuum on a piece, W/m^2.
using HeatFluxPiece = InterfacePiece<double>;

/// What the other side gives the continuum on an interface; an empty
/// vector: not given in this step.
struct ContinuumInterfaceLoad {
  /// The interface's name (its ContinuumInterface's).
  std::string name;
  /// Traction vector per node, Pa (the force per unit area the other side
  /// exerts on the continuum), linear between the nodes.
  std::vector<Vec2> traction;
  /// Tractions on pieces of the interface's edges, each linear along its
  /// piece (what a tied block region gives: one piece per block edge within
  /// a continuum edge, rockmass/fields/interface_ties.h); added to
  /// `traction`.
  std::vector<TractionPiece> traction_pieces;
  /// Fluid pressure per node, Pa (absolute, as the continuum's pressure).
  std::vector<double> pressure;
  /// Temperature per node, degC.
  std::vector<double> temperature;
  /// Fluid flowing into the continuum, m^3/s per m (written by the flow).
  InterfacePointLoads<double> fluid;
  /// Heat fluxes into the continuum on pieces of the interface's edges,
  /// each linear along its piece (what a tied block region's heat gives,
  /// thermal/conduction/thermal_ties.h), W/m^2.
  std::vector<HeatFluxPiece> heat_flux_pieces;
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
template <class Entry>
const Entry* find_interface(const std::vector<Entry>& all, const std::string& name) {
  for (const Entry& i : all)
    if (i.name == name) return &i;
  return nullptr;
}

/// The entry of that name, added (with only its name) when there is none.
ContinuumInterfaceLoad& interface_load(std::vector<ContinuumInterfaceLoad>& all,
                                       const std::string& name);

/// Where a point lies on an interface: on edge `edge` at s in [0, 1] from
/// its first node, `distance` (m) from it.
struct InterfacePlace {
  int edge = -1;
  double s = 0;
  double distance = std::numeric_limits<double>::infinity();
};

/// The nearest place on the interface's edges (the first of equally near
/// ones, so that both sides of the interface place a point alike).
InterfacePlace locate_on_interface(const ContinuumInterface& i, const Vec2& x);

/// The shape functions of a place: quadratic {first node, second node,
/// midpoint}, linear {first node, second node}.
std::array<double, 3> quadratic_weights(double s);
std::array<double, 2> linear_weights(double s);

/// The continuum's trace at a place: its displacement (quadratic along the
/// edge), pressure and temperature (linear). Pressure and temperature need
/// their vectors filled.
Vec2 displacement_at(const ContinuumInterface& i, const InterfacePlace& at);
double pressure_at(const ContinuumInterface& i, const InterfacePlace& at);
double temperature_at(const ContinuumInterface& i, const InterfacePlace& at);

/// The error of a process that finds, at its first step, interfaces
/// `what` ("its blocks lie along") but found none at its own start: it
/// came before the continuum in coupling.order, and would have run untied.
std::string tied_before_continuum(std::string_view process, std::string_view what);

/// How far from the interface a point may lie and still be on it: 1e-9 of
/// the interface's extent, and at least 1 nm.
double interface_tolerance(const ContinuumInterface& i);

/// A piece of a segment [a, b] along one of the interface's edges: the
/// edge, the piece's ends on it (s0 < s1) and the same ends on the segment
/// (t0, t1, from a to b).
struct SegmentPiece {
  int edge = -1;
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;
};
/// The pieces of the segment [a, b] along the interface's edges (within
/// interface_tolerance of them), in the edges' order; empty unless they
/// cover the whole segment.
std::vector<SegmentPiece> pieces_along(const ContinuumInterface& i, const Vec2& a, const Vec2& b);

}  // namespace fissure

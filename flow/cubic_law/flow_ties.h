// The fracture network's water tied to a continuum interface
// (docs/architecture.md 5, "A discrete region inside the continuum";
// docs/flow.md 9): the network's nodes that lie on an interface which takes
// fluid_flow (the mouths where its fractures meet the block region's
// outline). The scheme is the blocks' (rockmass/fields/interface_ties.h) at
// points: each mouth gives the continuum a flow Q (m^3/s per m, the
// `fluid` point loads of continuum_interface_loads), and in an update the
// network takes, at the mouth,
//   -Q + c (p_c(x) - p),
// Q the flow the continuum last took, p_c its pressure at the mouth's place
// (its linear trace, sampled with the shape functions it spreads Q with, so
// the transfer conserves the water) and c = the continuum's fluid impedance
// (k / (mu R) per unit length) times the interface's length per mouth: a
// Robin exchange (flow/network/node_conditions.h). After the update the
// mouth gives Q - c (p_c - p). A fixed point has p = p_c at every mouth, and
// the water that leaves one side enters the other at every pass. The rock
// between the mouths is impermeable to the network, so the continuum takes
// no flow there.
#pragma once

#include <string>
#include <vector>

#include "core/scene/exchanged_field.h"
#include "core/state/rock_mass.h"
#include "flow/network/node_conditions.h"
#include "rockmass/fields/continuum_interface.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/physical_quantities.h"

namespace fissure::flow {

class FlowTies {
 public:
  /// The network's nodes on an interface which takes fluid_flow. Throws
  /// SceneError for a node there whose pressure `conditions` fix (the
  /// continuum gives it).
  static FlowTies find(const FractureGraph& graph, const NodeConditions& conditions,
                       const RockMass& state);
  bool empty() const { return ties_.empty(); }
  std::size_t size() const { return ties_.size(); }

  /// The mouths' exchanges with the continuum's last pressures, and the
  /// flows it last took as sinks.
  void add_exchanges(const RockMass& state, NodeConditions& conditions) const;
  /// Gives the continuum the flows out of the network at the mouths'
  /// `pressure` (per graph node), from the exchanges of `conditions`.
  void give(RockMass& state, const NodeConditions& conditions,
            const std::vector<double>& pressure) const;
  /// Gives it none (the start).
  void give_none(RockMass& state) const;

  /// The flows given, m^3/s per m per mouth in the ties' order: the
  /// exchanged values and what a checkpoint holds.
  std::vector<double> values(const RockMass& state) const;
  void set_values(RockMass& state, const std::vector<double>& values) const;
  /// The flow given through each interface, m^3/s per m (> 0 into the
  /// continuum), by interface name.
  std::vector<std::pair<std::string, double>> outflows(const RockMass& state) const;

 private:
  struct Tie {
    int interface = -1;  ///< into names_
    int node = -1;       ///< the graph node
    Vec2 point;          ///< where the network was cut there
    InterfacePlace place;
    double conductance = 0;  ///< c, m^2/(s Pa)
  };
  /// Per interface, the flows of its ties in the ties' order.
  template <class Visit>
  void for_each_flow(auto& state, Visit&& visit) const;

  std::vector<std::string> names_;
  std::vector<Tie> ties_;  ///< grouped by interface
};

}  // namespace fissure::flow

// Named boundary conditions and wells of a scene (FlowControls) turned into
// per-node conditions (node_conditions.h) at a time t:
//  * pressure p: fixed p at every node of the boundary;
//  * head h:     fixed p = rho_f |g| h + rho_f g.x (p* = rho_f |g| h);
//  * flux Q:     Q (m^2/s, > 0 into the network) split equally among the
//                boundary's nodes (one node per fracture crossing);
//  * well:       its rate at the node it was placed on (locate_well).
// Each value is scaled by its piecewise-linear history. A node on two
// boundaries takes the later condition; a fixed pressure wins over a flux.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "flow/network/flow_conditions.h"
#include "flow/network/fluid.h"
#include "flow/network/node_conditions.h"
#include "rockmass/fracture_graph.h"

namespace fissure::flow {

/// Throws SceneError, naming the condition's scene line, for a condition whose
/// boundary holds no node of the network; the message lists the boundaries
/// that exist.
void check_condition_boundaries(const FractureGraph& graph,
                                std::span<const FlowBoundaryCondition> conditions);

/// The node a well injects at: the nearest node within `tolerance`, else a
/// new node splitting the nearest segment within `tolerance` (the graph is
/// changed). Throws SceneError when the point is on no fracture.
int locate_well(FractureGraph& graph, const FlowWell& well, double tolerance);

NodeConditions resolve_conditions(const FractureGraph& graph,
                                  std::span<const FlowBoundaryCondition> conditions,
                                  std::span<const FlowWell> wells, std::span<const int> well_nodes,
                                  const FluidProperties& fluid, const Vec2& gravity, double t);

/// Throws SceneError when there are two or more fixed-pressure conditions and
/// no cluster of the network joins any two of them (no flow path between the
/// pressure boundaries), naming them. `component` is per node (-1 outside).
void check_pressure_boundaries_connected(const FractureGraph& graph,
                                         std::span<const FlowBoundaryCondition> conditions,
                                         std::span<const int> component);

}  // namespace fissure::flow

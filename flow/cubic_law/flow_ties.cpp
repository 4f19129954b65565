#include "flow/cubic_law/flow_ties.h"

#include <fmt/format.h>

#include "core/base/errors.h"

namespace fissure::flow {

FlowTies FlowTies::find(const FractureGraph& graph, const NodeConditions& conditions,
                        const RockMass& state) {
  FlowTies out;
  const std::vector<ContinuumInterface>* interfaces = state.fields.find(kContinuumInterfaces);
  if (!interfaces) return out;
  for (const ContinuumInterface& i : *interfaces) {
    if (!i.takes.fluid_flow || i.edges.empty()) continue;
    const double tolerance = interface_tolerance(i);
    Vec2 lo = i.nodes[0], hi = i.nodes[0];
    for (const Vec2& p : i.nodes) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    const std::size_t first = out.ties_.size();
    for (int v = 0; v < graph.n_nodes(); ++v) {
      const Vec2& x = graph.nodes[v];
      if ((x.array() < lo.array() - tolerance).any() || (x.array() > hi.array() + tolerance).any())
        continue;
      const InterfacePlace place = locate_on_interface(i, x);
      if (place.distance > tolerance) continue;
      if (conditions.is_fixed(v))
        throw SceneError(fmt::format(
            "flow.conditions: found a fixed pressure at fracture node {} ({:g}, {:g}) m, on the "
            "continuum interface '{}' which takes fluid_flow; expected no flow condition there "
            "(the continuum gives the network its pressure)",
            v, x.x(), x.y(), i.name));
      out.ties_.push_back({static_cast<int>(out.names_.size()), v, x, place, 0});
    }
    if (out.ties_.size() == first) continue;
    // c: the continuum's conductance per unit length times each mouth's
    // share of the interface (docs/architecture.md 5).
    double perimeter = 0;
    for (const auto& [a, b] : i.edges) perimeter += (i.nodes[b] - i.nodes[a]).norm();
    const double share = perimeter / static_cast<double>(out.ties_.size() - first);
    for (std::size_t k = first; k < out.ties_.size(); ++k)
      out.ties_[k].conductance = i.impedance.fluid * share;
    FISSURE_CHECK(i.impedance.fluid > 0, SceneError,
                  "continuum: the interface '" << i.name
                                               << "' takes fluid_flow but its rock conducts no "
                                                  "water; expected a permeability > 0 beside it");
    out.names_.push_back(i.name);
  }
  return out;
}

template <class Visit>
void FlowTies::for_each_flow(auto& state, Visit&& visit) const {
  if (names_.empty()) return;
  auto& loads = state.fields.get(kContinuumInterfaceLoads);
  std::size_t k = 0;
  for (std::size_t n = 0; n < names_.size(); ++n) {
    auto* load = find_interface(loads, names_[n]);
    FISSURE_CHECK(load && load->fluid.values.size() == load->fluid.points.size(), std::logic_error,
                  "flow: the fluid loads of interface '" << names_[n] << "' are missing");
    for (auto& q : load->fluid.values) visit(ties_[k++], q);
  }
}

void FlowTies::add_exchanges(const RockMass& state, NodeConditions& conditions) const {
  const auto& interfaces = state.fields.get(kContinuumInterfaces);
  for_each_flow(state, [&](const Tie& t, double q) {
    const ContinuumInterface& i = *find_interface(interfaces, names_[t.interface]);
    conditions.source[t.node] -= q;
    conditions.exchange_conductance[t.node] += t.conductance;
    conditions.exchange_pressure[t.node] = pressure_at(i, t.place);
  });
}

void FlowTies::give(RockMass& state, const NodeConditions& conditions,
                    const std::vector<double>& pressure) const {
  for_each_flow(state, [&](const Tie& t, double& q) {
    q -= t.conductance * (conditions.exchange_pressure[t.node] - pressure[t.node]);
  });
}

void FlowTies::give_none(RockMass& state) const {
  auto& loads = state.fields.get_or_add(kContinuumInterfaceLoads);
  for (std::size_t n = 0; n < names_.size(); ++n) {
    InterfacePointLoads<double>& fluid = interface_load(loads, names_[n]).fluid;
    fluid = {};
    for (const Tie& t : ties_)
      if (t.interface == static_cast<int>(n)) fluid.points.push_back(t.point);
    fluid.values.assign(fluid.points.size(), 0.0);
  }
}

std::vector<double> FlowTies::values(const RockMass& state) const {
  std::vector<double> out;
  out.reserve(ties_.size());
  for_each_flow(state, [&](const Tie&, double q) { out.push_back(q); });
  return out;
}

void FlowTies::set_values(RockMass& state, const std::vector<double>& values) const {
  FISSURE_CHECK(values.size() == ties_.size(), IoError,
                "flow: " << values.size() << " interface flows for " << ties_.size()
                         << " tied fracture nodes");
  std::size_t k = 0;
  for_each_flow(state, [&](const Tie&, double& q) { q = values[k++]; });
}

std::vector<std::pair<std::string, double>> FlowTies::outflows(const RockMass& state) const {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& name : names_) out.emplace_back(name, 0.0);
  for_each_flow(state, [&](const Tie& t, double q) { out[t.interface].second += q; });
  return out;
}

}  // namespace fissure::flow

// Top-level key `flow` (docs/scene-reference.md section 11): fluid,
// apertures, network source, transient scheme, HM coupling and the linear
// solver, and their consistency with `physics`. Conditions and wells are in
// read_flow_conditions.cpp.
#include <fmt/format.h>

#include <limits>

#include "core/scene/read_flow.h"
#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_keys.h"

namespace fissure {

namespace {

void read_fluid(const ConfigNode& node, FlowControls& flow) {
  ConfigMap map(node, scene_keys::flow_fluid);
  map.read("density", flow.density, quantity::density, Range::positive());
  map.read("viscosity", flow.viscosity, quantity::viscosity, Range::positive());
  map.read("bulk_modulus", flow.bulk_modulus, quantity::pressure, Range::positive());
}

void read_apertures(const ConfigNode& node, FlowControls& flow) {
  ConfigMap map(node, scene_keys::flow_apertures);
  map.read("initial", flow.initial_aperture, quantity::length, Range::positive());
  map.read("residual", flow.residual_aperture, quantity::length, Range::positive());
  if (auto m = map.optional("maximum")) {
    if (auto v = m->quantity(quantity::length, Range::non_negative())) {
      if (*v > 0 && *v <= flow.residual_aperture)
        m->error(
            fmt::format("found {}; expected 0 (no cap) or more than the residual aperture "
                        "({} m)",
                        m->found(), flow.residual_aperture));
      else
        flow.maximum_aperture = *v;
    }
  }
}

void read_traces(const ConfigNode& node, FlowControls& flow) {
  const auto items = node.list("fracture traces {from, to, aperture}", true);
  if (!items) return;
  for (const ConfigNode& item : *items) {
    ConfigMap map(item, scene_keys::flow_trace);
    FlowTrace t;
    t.aperture = flow.initial_aperture;
    if (auto n = map.required("from", "a point [x, y]"))
      if (auto p = n->vec2(quantity::length)) t.from = *p;
    if (auto n = map.required("to", "a point [x, y]")) {
      if (auto p = n->vec2(quantity::length)) {
        t.to = *p;
        if ((t.to - t.from).norm() == 0)
          n->error("found the same point as `from`; expected a trace of non-zero length");
      }
    }
    map.read("aperture", t.aperture, quantity::length, Range::positive());
    flow.traces.push_back(t);
  }
}

void read_network(const ConfigNode& node, FlowControls& flow) {
  using Source = FlowControls::NetworkSource;
  ConfigMap map(node, scene_keys::flow_network);
  std::optional<ConfigNode> source_node = map.optional("source");
  std::optional<std::string> source;
  constexpr std::string_view kSources[] = {"blocks", "traces", "rock_mass"};
  if (source_node) source = source_node->choice(kSources);
  if (auto t = map.optional("traces")) read_traces(*t, flow);
  if (!source) source = flow.traces.empty() ? "blocks" : "traces";
  flow.network = *source == "blocks"   ? Source::Blocks
                 : *source == "traces" ? Source::Traces
                                       : Source::RockMass;
  if (flow.network == Source::Traces && flow.traces.empty() && source_node)
    source_node->error("found 'traces' but no flow.network.traces; expected a list of traces");
  if (flow.network != Source::Traces && !flow.traces.empty() && source_node)
    source_node->error("found '" + *source +
                       "' together with flow.network.traces; expected source traces, or no traces");
  if (auto d = map.optional("domain")) {
    const auto corners = d->list("two corners [[x0, y0], [x1, y1]]", true);
    if (corners && corners->size() != 2) {
      d->error("found " + d->found() + "; expected two corners [[x0, y0], [x1, y1]]");
    } else if (corners) {
      auto lo = (*corners)[0].vec2(quantity::length), hi = (*corners)[1].vec2(quantity::length);
      if (lo && hi) {
        if ((*hi - *lo).minCoeff() <= 0)
          d->error(
              "found corners that do not span a box; expected [[x0, y0], [x1, y1]] with "
              "x0 < x1 and y0 < y1");
        else
          flow.domain = std::make_pair(*lo, *hi);
      }
    }
    if (flow.network != Source::Traces)
      d->error_at_key("found a clipping domain for network source '" +
                      std::string(*source == "blocks" ? "blocks" : "rock_mass") +
                      "'; expected it only with source traces");
  }
}

void read_transient(const ConfigNode& node, FlowControls& flow) {
  using Scheme = FlowControls::Transient::Scheme;
  ConfigMap map(node, scene_keys::flow_transient);
  FlowControls::Transient t;
  constexpr std::string_view kSchemes[] = {"cvode", "bdf2", "backward_euler", "explicit"};
  if (auto s = map.optional("scheme"))
    if (auto scheme = s->choice(kSchemes))
      t.scheme = *scheme == "cvode"            ? Scheme::Cvode
                 : *scheme == "bdf2"           ? Scheme::Bdf2
                 : *scheme == "backward_euler" ? Scheme::BackwardEuler
                                               : Scheme::Explicit;
  map.read("time_step", t.time_step, quantity::time, Range::non_negative());
  map.read("relative_tolerance", t.relative_tolerance, quantity::dimensionless, Range::open(0, 1));
  map.read("absolute_tolerance", t.absolute_tolerance, quantity::pressure, Range::positive());
  flow.transient = t;
}

void read_hm(const ConfigNode& node, FlowControls& flow) {
  ConfigMap map(node, scene_keys::flow_hm);
  map.read_required("normal_stiffness", flow.hm.normal_stiffness, quantity::normal_stiffness,
                    Range::positive());
  map.read("dilation_angle", flow.hm.dilation_angle, quantity::angle,
           Range::closed_open(0, 90 * quantity::kDegree));
  map.read("dilation_limit", flow.hm.dilation_limit, quantity::length, Range::non_negative());
  map.read("coupling_interval", flow.hm.coupling_interval, quantity::time, Range::non_negative());
}

}  // namespace

std::string describe_location(const ConfigNode& node) {
  const SourceLocation& l = node.location();
  return fmt::format("{}:{}:{}: {}", l.file, l.line, l.column, node.path());
}

void read_flow(ConfigMap& top, SceneDraft& draft) {
  Scene& scene = draft.scene;
  const bool active = scene.has_physics("flow");
  std::optional<ConfigNode> node = top.optional("flow");
  if (!node) {
    if (active)
      top.report_missing("flow",
                         "a flow section, because physics lists flow (see docs/flow.md; with all "
                         "defaults, `flow: {}` is a network of the block contacts without "
                         "boundary conditions)");
    return;
  }
  if (!active && draft.physics_read)
    node->error_at_key(
        "found a flow section, but physics does not list flow; expected 'flow' in "
        "physics, or no flow section");

  FlowControls& flow = scene.flow;
  ConfigMap map(*node, scene_keys::flow);
  if (auto n = map.optional("fluid")) read_fluid(*n, flow);
  map.read("gravity", flow.gravity);
  if (auto n = map.optional("apertures")) read_apertures(*n, flow);
  if (auto n = map.optional("network")) read_network(*n, flow);
  if (auto n = map.optional("transient")) read_transient(*n, flow);
  if (auto n = map.optional("solver")) read_linear_solver(*n, scene_keys::flow_solver, flow.solver);

  // Heads need gravity: p* = p - rho g.x with a non-zero g.
  const bool gravity_on = flow.gravity && scene.gravity.norm() > 0;
  read_flow_conditions(map, draft, gravity_on);

  // The HM coupling needs mechanics, and mechanics with flow needs it.
  const bool mechanics = scene.has_physics("mechanics");
  if (auto n = map.optional("hm")) {
    if (!mechanics && draft.physics_read)
      n->error_at_key(
          "found an hm section, but physics does not list mechanics; expected "
          "'mechanics' in physics, or no hm section");
    read_hm(*n, flow);
  } else if (mechanics && active) {
    map.report_missing("hm",
                       "an hm section with at least normal_stiffness, because physics "
                       "lists mechanics and flow");
  }
  if (mechanics && active && flow.network == FlowControls::NetworkSource::Traces)
    map.node().error(
        "found network source 'traces' with mechanics; expected source blocks or "
        "rock_mass (traces carry no block faces to load and to open)");
}

}  // namespace fissure

// The scene's `flow` section (docs/scene-reference.md section 11): fluid,
// apertures, network source, transient scheme, HM coupling and the linear
// solver, and their consistency with the other physics. Conditions and wells
// are in read_flow_conditions.cpp.
#include <fmt/format.h>

#include <limits>

#include "core/scene/read_linear_solver.h"
#include "core/scene/scene_keys.h"
#include "core/scene/time_limits.h"
#include "flow/cubic_law/flow_exchanged_fields.h"
#include "flow/cubic_law/read_flow_settings.h"
#include "flow/network/read_fluid.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/fracture_flow.h"
#include "rockmass/fracture_graph.h"
#include "rockmass/physical_quantities.h"

namespace fissure {

namespace {

constexpr std::string_view kFlow[] = {"fluid",        "gravity",    "apertures", "network",
                                      "regions",      "conditions", "wells",     "initial_pressure",
                                      "initial_head", "transient",  "hm",        "solver"};
constexpr std::string_view kApertures[] = {"initial", "residual", "maximum"};
constexpr std::string_view kNetwork[] = {"source", "domain", "traces"};
constexpr std::string_view kTrace[] = {"from", "to", "aperture"};
constexpr std::string_view kTransient[] = {"scheme", "time_step", "relative_tolerance",
                                           "absolute_tolerance"};
constexpr std::string_view kHm[] = {"normal_stiffness", "dilation_angle", "dilation_limit",
                                    "coupling_interval"};
const KeyTable flow_table{"flow", kFlow};
const KeyTable fluid_table{"flow.fluid", flow::kFluidKeys};
const KeyTable apertures_table{"flow.apertures", kApertures};
const KeyTable network_table{"flow.network", kNetwork};
const KeyTable trace_table{"flow.network.traces[]", kTrace};
const KeyTable transient_table{"flow.transient", kTransient};
const KeyTable hm_table{"flow.hm", kHm};
const KeyTable solver_table{"flow.solver", scene_keys::linear_solver};
const KeyTable* const kTables[] = {
    &flow_table,      &fluid_table,        &apertures_table,       &network_table,
    &trace_table,     &flow::region_table, &flow::condition_table, &flow::well_table,
    &transient_table, &hm_table,           &solver_table};

void read_apertures(const ConfigNode& node, FlowControls& flow) {
  ConfigMap map(node, apertures_table);
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
    ConfigMap map(item, trace_table);
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
  ConfigMap map(node, network_table);
  std::optional<ConfigNode> source_node = map.optional("source");
  std::optional<std::string> source;
  constexpr std::string_view kSources[] = {"blocks", "traces", "rock_mass"};
  if (source_node) source = source_node->choice(kSources);
  std::optional<ConfigNode> traces_node = map.optional("traces");
  if (traces_node) read_traces(*traces_node, flow);
  if (source_node || traces_node)
    flow.network_path = (source_node ? *source_node : *traces_node).located_path();
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

void read_transient(const ConfigNode& node, FlowControls& flow, const TimeControls& time) {
  using Scheme = FlowControls::Transient::Scheme;
  ConfigMap map(node, transient_table);
  FlowControls::Transient t;
  constexpr std::string_view kSchemes[] = {"cvode", "bdf2", "backward_euler", "explicit"};
  if (auto s = map.optional("scheme"))
    if (auto scheme = s->choice(kSchemes))
      t.scheme = *scheme == "cvode"            ? Scheme::Cvode
                 : *scheme == "bdf2"           ? Scheme::Bdf2
                 : *scheme == "backward_euler" ? Scheme::BackwardEuler
                                               : Scheme::Explicit;
  if (auto step = map.optional("time_step"))
    if (auto dt = step->quantity(quantity::time, Range::non_negative())) {
      t.time_step = *dt;
      check_time_step(*step, *dt, time);  // 0: the coupling step
    }
  map.read("relative_tolerance", t.relative_tolerance, quantity::dimensionless, Range::open(0, 1));
  map.read("absolute_tolerance", t.absolute_tolerance, quantity::pressure, Range::positive());
  flow.transient = t;
}

/// flow.hm.coupling_interval, deprecated: the flow's interval of the
/// `coupling` section (coupling.intervals.flow).
void read_deprecated_interval(const ConfigNode& node, SectionContext& context) {
  context.deprecated(node,
                     "`coupling: {intervals: {flow: ...}}` instead (docs/scene-reference.md "
                     "section 8); it is read as that");
  const std::optional<double> interval = node.quantity(quantity::time, Range::non_negative());
  CouplingSettings& coupling = context.scene().coupling;
  std::map<std::string, double>& intervals = coupling.intervals;
  if (intervals.count("flow") || coupling.own_intervals.count("flow"))
    node.error_at_key(
        "found both flow.hm.coupling_interval and coupling.intervals.flow; expected "
        "coupling.intervals.flow only");
  else if (interval && *interval > 0)
    intervals["flow"] = *interval;
}

void read_hm(const ConfigNode& node, FlowControls& flow, SectionContext& context) {
  ConfigMap map(node, hm_table);
  FlowControls::Hm& hm = flow.hm.emplace();
  map.read_required("normal_stiffness", hm.normal_stiffness, quantity::joint_normal_stiffness,
                    Range::positive());
  map.read("dilation_angle", hm.dilation_angle, quantity::angle,
           Range::closed_open(0, 90 * quantity::kDegree));
  map.read("dilation_limit", hm.dilation_limit, quantity::length, Range::non_negative());
  if (auto n = map.optional("coupling_interval")) read_deprecated_interval(*n, context);
}

void read_flow(const ConfigNode& node, SectionContext& context) {
  Scene& scene = context.scene();
  const bool active = scene.has_physics("flow");
  FlowControls& flow = scene.sections.set(flow::kSettings, FlowControls{});
  ConfigMap map(node, flow_table);
  flow.network_path = node.located_path();  // the default source: blocks
  if (auto n = map.optional("fluid")) flow::read_fluid(*n, fluid_table, flow.fluid);
  map.read("gravity", flow.gravity);
  if (auto n = map.optional("apertures")) read_apertures(*n, flow);
  if (auto n = map.optional("network")) read_network(*n, flow);
  if (auto n = map.optional("transient")) read_transient(*n, flow, scene.time);
  if (auto n = map.optional("solver")) read_linear_solver(*n, solver_table, flow.solver);

  // Heads need gravity: p* = p - rho g.x with a non-zero g.
  const bool gravity_on = flow.gravity && scene.gravity.norm() > 0;
  read_flow_conditions(map, flow, gravity_on);

  // The HM coupling needs the block contacts (the mechanics writes them),
  // and a scene with both needs the coupling.
  const bool mechanics = provides(scene, kContacts.name);
  if (auto n = map.optional("hm")) {
    if (!mechanics && context.physics_read())
      n->error_at_key(
          "found an hm section, but physics does not list mechanics; expected "
          "'mechanics' in physics, or no hm section");
    read_hm(*n, flow, context);
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

/// What the flow writes in every scene (CubicLawProcess::writes() starts from it).
constexpr std::string_view kProvides[] = {kFractureGraph.name, kFractureFlow.name};

}  // namespace

namespace flow {
const SectionReader kFlowSection{
    "flow",
    "a flow section, because physics lists flow (see docs/flow.md; with all defaults, `flow: "
    "{}` is a network of the block contacts without boundary conditions)",
    &read_flow,
    nullptr,
    kTables,
    {},
    false,
    kProvides,
    kExchangedFields};
}  // namespace flow

}  // namespace fissure

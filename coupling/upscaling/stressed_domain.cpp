#include "coupling/upscaling/stressed_domain.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/base/errors.h"
#include "core/state/rock_mass.h"
#include "coupling/process_registry.h"
#include "flow/hm/fracture_walls.h"
#include "flow/hm/hm_apertures.h"
#include "flow/rev/permeability.h"
#include "rockmass/fields/contacts.h"
#include "rockmass/fields/pressure_loads.h"
#include "rockmass/generate_rock_mass.h"

namespace fissure {

namespace {

/// Rejected updates of one domain before it is given up as not at rest.
constexpr int kMaxRetries = 8;

/// The rock mass of the square: its traces as explicit fractures, cut
/// with the scene's material, tolerances and limits.
GeneratedRockMass cut_square(const RockMassSpec& scene_spec,
                             const std::vector<FractureTrace>& traces, double size,
                             const Eigen::Vector2d& stress) {
  RockMassSpec spec;
  const double h = size / 2;
  spec.domain = {Vec2(-h, -h), Vec2(h, -h), Vec2(h, h), Vec2(-h, h)};
  spec.material = scene_spec.material;
  spec.merge_tolerance = scene_spec.merge_tolerance;
  spec.max_blocks = scene_spec.max_blocks;
  spec.max_fractures = scene_spec.max_fractures;
  spec.initial_stress = Eigen::Vector3d(stress(0), stress(1), 0);
  spec.fractures.reserve(traces.size());
  for (const FractureTrace& t : traces)
    spec.fractures.push_back(FractureSpec{t.a, t.b, t.joint, t.aperture});
  return generate_rock_mass(spec);
}

/// The side of the square [-h, h]^2 that the edge a -> b lies on (its
/// outward normal), or nothing.
std::optional<Vec2> side_normal(const Vec2& a, const Vec2& b, double h, double tol) {
  if (std::abs(a.x() - h) < tol && std::abs(b.x() - h) < tol) return Vec2(1, 0);
  if (std::abs(a.x() + h) < tol && std::abs(b.x() + h) < tol) return Vec2(-1, 0);
  if (std::abs(a.y() - h) < tol && std::abs(b.y() - h) < tol) return Vec2(0, 1);
  if (std::abs(a.y() + h) < tol && std::abs(b.y() + h) < tol) return Vec2(0, -1);
  return std::nullopt;
}

/// The right and top sides loaded by `stress` (principal along them): a
/// pressure -n.sigma.n on every block edge along them.
std::vector<EdgePressureLoad> side_loads(const std::vector<Block>& blocks, int n_rock, double size,
                                         const Eigen::Vector2d& stress) {
  const double h = size / 2, tol = 1e-9 * size;
  std::vector<EdgePressureLoad> loads;
  for (int b = 0; b < n_rock; ++b) {
    const Polygon& p = blocks[b].polygon;
    for (int v = 0; v < p.n_vertices(); ++v) {
      const Vec2 &a = p.vertices[v], &e = p.vertices[p.next(v)];
      const auto n = side_normal(a, e, h, tol);
      if (n && (n->x() > 0 || n->y() > 0)) {
        const double pressure = -(n->x() != 0 ? stress(0) : stress(1));
        loads.push_back({b, a, e, pressure, pressure, *n});
      }
    }
  }
  return loads;
}

/// The rollers of the left and bottom sides: fixed platens outside them,
/// on the frictionless stiff joint `joint`, prestressed like the rock.
void add_platens(std::vector<BlockSpec>& blocks, double size, int material, int joint,
                 const Eigen::Vector2d& stress) {
  const double h = size / 2, t = 0.1 * size;
  auto platen = [&](std::string name, Vec2 lo, Vec2 hi) {
    BlockSpec b;
    b.name = std::move(name);
    b.polygon = Polygon({lo, Vec2(hi.x(), lo.y()), hi, Vec2(lo.x(), hi.y())});
    b.material = material;
    b.joint = joint;
    b.fixed = true;
    b.initial_stress = Eigen::Vector3d(stress(0), stress(1), 0);
    blocks.push_back(std::move(b));
  };
  platen("platen_left", Vec2(-h - t, -h - t), Vec2(-h, h + t));
  platen("platen_bottom", Vec2(-h, -h - t), Vec2(h + t, -h));
}

/// Of the closed contacts between rock blocks (not the platens'), the
/// share that slips.
double slip_fraction(const std::vector<ContactRecord>* contacts, int n_rock) {
  if (!contacts) return 0;
  long sliding = 0, locked = 0;
  for (const ContactRecord& c : *contacts) {
    if (c.block_i >= n_rock || c.block_j >= n_rock) continue;
    if (c.state == ContactState::Sliding) ++sliding;
    if (c.state == ContactState::Locked) ++locked;
  }
  return sliding + locked > 0 ? static_cast<double>(sliding) / static_cast<double>(sliding + locked)
                              : 0;
}

/// The process's statistics: its cycles, whether every update reached its
/// ratio.
flow::DomainMechanics mechanics_of(const Process& process) {
  flow::DomainMechanics m;
  const nlohmann::json s = process.statistics();
  m.cycles = s.value("cycles", 0L);
  m.equilibrium = s.value("unsolved_updates", 0L) == 0;
  return m;
}

}  // namespace

flow::DomainSolution solve_stressed_domain(const StressedDomainSetup& setup,
                                           const std::vector<FractureTrace>& traces, double size,
                                           const Eigen::Vector2d& stress,
                                           StressedDomainDetail* detail) {
  const Scene& bare = *setup.scene;
  GeneratedRockMass cut = cut_square(bare.sections.get(kRockMassSpec), traces, size, stress);

  // 1. The domain's scene: the bare scene's settings, the square's blocks.
  Scene scene = bare;
  const int n_rock = static_cast<int>(cut.blocks.size());
  scene.blocks = std::move(cut.blocks);
  add_platens(scene.blocks, size, bare.sections.get(kRockMassSpec).material, setup.platen_joint,
              stress);
  scene.initial_fields = {};
  scene.initial_fields.set(kFractureGraph, cut.fractures);
  RockMass state = RockMass::from_scene(scene);
  const BlockReference reference = initial_geometry(state.blocks);

  // 2. At rest under the sides' loads.
  std::unique_ptr<Process> process = create_process(scene, setup.process);
  process->initialize(state);
  state.fields.set(kPressureLoads, side_loads(state.blocks, n_rock, size, stress));
  // A rejected update (a corner pressed deeper than the rounding length:
  // the step was too long) is retried with the process's shorter step.
  StepReport report;
  int retries = 0;
  do report = process->advance(state, 0, 1);
  while (report.status == StepReport::Status::Retry && ++retries < kMaxRetries);
  const bool settled = report.status == StepReport::Status::Ok;
  flow::DomainSolution out;
  out.mechanics = mechanics_of(*process);
  out.mechanics.blocks = n_rock;
  out.mechanics.equilibrium = out.mechanics.equilibrium && settled;
  const std::vector<ContactRecord>* contacts = state.fields.find(kContacts);
  out.mechanics.contacts = contacts ? static_cast<int>(contacts->size()) : 0;
  out.mechanics.slip_fraction = slip_fraction(contacts, n_rock);
  // Blocks not at rest (joints that cannot hold the stress: a mechanism)
  // have no permeability: the domain counts as not connected.
  if (!out.mechanics.equilibrium) return out;

  // 3. Apertures: segments between two blocks by their walls and contacts,
  //    pieces inside a block by the applied stress resolved on them (their
  //    walls are one block: they close but cannot slip or open).
  const FractureGraph& g = cut.fractures;
  flow::FractureApertureLaws laws(scene.joints, setup.aperture_law);
  laws.assign(g, state.blocks, state.joints, "the REV study's rock mass");
  const std::vector<flow::SegmentWalls> walls =
      flow::segment_walls(g, g.nodes, block_maps(state.blocks, reference));
  static const std::vector<ContactRecord> kNoContacts;
  // The walls touch as cut, each segment closed by the applied stress on
  // its plane: a wall separation is an opening beyond that closure.
  std::vector<double> applied(g.n_segments()), closure(g.n_segments());
  for (int s = 0; s < g.n_segments(); ++s) {
    const Vec2 t = (g.nodes[g.segments[s].node_b] - g.nodes[g.segments[s].node_a]).normalized();
    applied[s] = -(t.y() * t.y() * stress(0) + t.x() * t.x() * stress(1));
    closure[s] = laws.of_segment(s).closure(applied[s], g.length(s));
  }
  std::vector<double> e_a, e_b;
  flow::hm_apertures(g, walls, contacts ? *contacts : kNoContacts, laws, e_a, e_b, nullptr,
                     closure);
  std::vector<flow::FractureApertureLaw> joint_laws;
  for (const JointProperties& j : scene.joints) joint_laws.emplace_back(j, setup.aperture_law);
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    if (seg.left.block < 0 || seg.left.block != seg.right.block) continue;
    int joint = seg.fracture >= 0 ? traces[seg.fracture].joint : -1;
    if (joint < 0) joint = scene.default_joint;
    const flow::EndAperture e =
        joint_laws[joint].at(flow::WallEnd{0, applied[s], 0}, seg.aperture, g.length(s));
    e_a[s] = e_b[s] = e.aperture;
  }

  // 4. The deformed network's permeability (in the square's frame, as cut).
  const flow::DomainPermeability k =
      flow::domain_permeability(g, size, setup.viscosity, setup.pressure_drop, e_a, e_b);
  out.k = k.k;
  out.n_nodes = k.n_nodes;
  out.n_segments = k.n_segments;
  out.connected = k.connected;
  if (detail) {
    detail->aperture_a = std::move(e_a);
    detail->aperture_b = std::move(e_b);
    detail->graph = g;
    detail->blocks = state.blocks;
  }
  return out;
}

}  // namespace fissure

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

/// The sides loaded by `stress` (sxx, syy, sxy; tension +): the traction
/// sigma.n on every block edge along the right and top sides, and along the
/// left and bottom sides too when `all_sides` (a floating square; else the
/// rollers carry their normal stress): a pressure -n.sigma.n and a shear
/// t.sigma.n along the side (none while the square is aligned with the
/// principal axes).
std::vector<EdgePressureLoad> side_loads(const std::vector<Block>& blocks, int n_rock, double size,
                                         const Eigen::Vector3d& stress, bool all_sides) {
  const double h = size / 2, tol = 1e-9 * size;
  Eigen::Matrix2d sigma;
  sigma << stress(0), stress(2), stress(2), stress(1);
  std::vector<EdgePressureLoad> loads;
  for (int b = 0; b < n_rock; ++b) {
    // The sides' edges as cut, loaded where they are now.
    const Polygon& p = blocks[b].polygon;
    const std::vector<Vec2>& cut = blocks[b].initial_vertices;
    for (int v = 0; v < p.n_vertices(); ++v) {
      const Vec2 &a = p.vertices[v], &e = p.vertices[p.next(v)];
      const auto n = side_normal(cut[v], cut[p.next(v)], h, tol);
      if (!n || !(all_sides || n->x() > 0 || n->y() > 0)) continue;
      const Vec2 traction = sigma * *n;
      const double pressure = -n->dot(traction);
      const double shear = (cut[p.next(v)] - cut[v]).normalized().dot(traction);
      loads.push_back({b, a, e, pressure, pressure, *n, shear, shear});
    }
  }
  return loads;
}

/// The rollers of the left and bottom sides: one fixed L-shaped platen
/// around them (its inner corner is reflex, so a block in the square's
/// corner bears on both its faces alike), on the frictionless stiff joint
/// `joint`, prestressed like the rock.
void add_platen(std::vector<BlockSpec>& blocks, double size, int material, int joint,
                const Eigen::Vector2d& stress) {
  const double h = size / 2, o = h + 0.1 * size;
  BlockSpec b;
  b.name = "platen";
  b.polygon =
      Polygon({Vec2(-o, -o), Vec2(o, -o), Vec2(o, -h), Vec2(-h, -h), Vec2(-h, o), Vec2(-o, o)});
  b.material = material;
  b.joint = joint;
  b.fixed = true;
  b.initial_stress = Eigen::Vector3d(stress(0), stress(1), 0);
  blocks.push_back(std::move(b));
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

/// The vertices of the rock blocks on the four sides, whose mean moves are
/// the square's mean strains times its side.
struct LoadedSides {
  std::vector<std::pair<int, int>> right, top, left, bottom;  ///< (block, vertex)

  LoadedSides(const std::vector<Block>& blocks, int n_rock, double size) {
    const double h = size / 2, tol = 1e-9 * size;
    for (int b = 0; b < n_rock; ++b)
      for (int v = 0; v < blocks[b].polygon.n_vertices(); ++v) {
        const Vec2& x = blocks[b].initial_vertices[v];
        if (std::abs(x.x() - h) < tol) right.emplace_back(b, v);
        if (std::abs(x.y() - h) < tol) top.emplace_back(b, v);
        if (std::abs(x.x() + h) < tol) left.emplace_back(b, v);
        if (std::abs(x.y() + h) < tol) bottom.emplace_back(b, v);
      }
  }
  /// Mean (e_xx, e_yy, gamma_xy) of the blocks' moves from their initial
  /// vertices, between opposite sides: e_xx = (u_x(right) - u_x(left)) / L,
  /// gamma = (u_y(right) - u_y(left) + u_x(top) - u_x(bottom)) / L.
  Eigen::Vector3d strain(const std::vector<Block>& blocks, double size) const {
    auto mean_move = [&](const std::vector<std::pair<int, int>>& points, int axis) {
      double sum = 0;
      for (const auto& [b, v] : points)
        sum += blocks[b].polygon.vertices[v][axis] - blocks[b].initial_vertices[v][axis];
      return points.empty() ? 0.0 : sum / static_cast<double>(points.size());
    };
    return Eigen::Vector3d(mean_move(right, 0) - mean_move(left, 0),
                           mean_move(top, 1) - mean_move(bottom, 1),
                           mean_move(right, 1) - mean_move(left, 1) + mean_move(top, 0) -
                               mean_move(bottom, 0)) /
           size;
  }
};

/// The process's statistics: its cycles, whether every update reached its
/// ratio.
flow::DomainMechanics mechanics_of(const Process& process) {
  flow::DomainMechanics m;
  const nlohmann::json s = process.statistics();
  m.cycles = s.value("cycles", 0L);
  m.equilibrium = s.value("unsolved_updates", 0L) == 0;
  return m;
}

/// One update solved to rest, a rejected one (a corner pressed deeper than
/// the rounding length: the step was too long) retried with the process's
/// shorter step, up to kMaxRetries times. Whether it was kept and every
/// update so far reached the solve ratio: the blocks are at rest.
bool solve_to_rest(Process& process, RockMass& state) {
  StepReport report;
  int retries = 0;
  do report = process.advance(state, 0, 1);
  while (report.status == StepReport::Status::Retry && ++retries < kMaxRetries);
  return report.status == StepReport::Status::Ok && mechanics_of(process).equilibrium;
}

/// The tangent compliance of the square of `scene` (its rock blocks as cut,
/// prestressed, no platen) floating under its stress on all four sides: at
/// rest under it, then the stress grows by the increment along x
/// (compression), along y, and in shear, each solved to rest (the joints
/// keep their states); the strains between opposite sides per unit stress
/// are its columns (tension +). Rollers would not do for this: they hold
/// every block on a side at one normal displacement, which simple shear
/// violates (a trial measured 0.32 of one set's 1/(k_s s)). The loads
/// balance, so the square needs no support; its rigid-body moves drop out
/// of the strains. Zero when it does not come to rest.
Eigen::Matrix3d floating_compliance(const Scene& scene, const StressedDomainSetup& setup,
                                    double size, const Eigen::Vector2d& stress) {
  const int n_rock = static_cast<int>(scene.blocks.size());
  RockMass state = RockMass::from_scene(scene);
  std::unique_ptr<Process> process = create_process(scene, setup.process);
  process->initialize(state);
  Eigen::Vector3d loaded(stress(0), stress(1), 0);
  state.fields.set(kPressureLoads, side_loads(state.blocks, n_rock, size, loaded, true));
  if (!solve_to_rest(*process, state)) return Eigen::Matrix3d::Zero();
  const LoadedSides sides(state.blocks, n_rock, size);
  const double d = setup.compliance_increment;
  Eigen::Vector3d before = sides.strain(state.blocks, size);
  Eigen::Matrix3d compliance;
  for (int j = 0; j < 3; ++j) {
    const double increment = j < 2 ? -d : d;
    loaded(j) += increment;
    state.fields.set(kPressureLoads, side_loads(state.blocks, n_rock, size, loaded, true));
    if (!solve_to_rest(*process, state)) return Eigen::Matrix3d::Zero();
    const Eigen::Vector3d after = sides.strain(state.blocks, size);
    compliance.col(j) = (after - before) / increment;
    before = after;
  }
  return compliance;
}

}  // namespace

flow::DomainSolution solve_stressed_domain(const StressedDomainSetup& setup,
                                           const std::vector<FractureTrace>& traces, double size,
                                           const Eigen::Vector2d& stress) {
  const Scene& bare = *setup.scene;
  GeneratedRockMass cut = cut_square(bare.sections.get(kRockMassSpec), traces, size, stress);

  // 1. The domain's scene: the bare scene's settings, the square's blocks.
  Scene scene = bare;
  const int n_rock = static_cast<int>(cut.blocks.size());
  scene.blocks = std::move(cut.blocks);
  add_platen(scene.blocks, size, bare.sections.get(kRockMassSpec).material, setup.platen_joint,
             stress);
  scene.initial_fields = {};
  scene.initial_fields.set(kFractureGraph, cut.fractures);
  RockMass state = RockMass::from_scene(scene);
  const BlockReference reference = initial_geometry(state.blocks);

  // 2. At rest under the sides' loads.
  std::unique_ptr<Process> process = create_process(scene, setup.process);
  process->initialize(state);
  state.fields.set(kPressureLoads, side_loads(state.blocks, n_rock, size,
                                              Eigen::Vector3d(stress(0), stress(1), 0), false));
  const bool settled = solve_to_rest(*process, state);
  flow::DomainSolution out;
  out.mechanics = mechanics_of(*process);
  out.mechanics.blocks = n_rock;
  out.mechanics.equilibrium = settled;
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
  for (int s = 0; s < g.n_segments(); ++s) {
    const FractureSegment& seg = g.segments[s];
    if (seg.left.block < 0 || seg.left.block != seg.right.block) continue;
    int joint = seg.fracture >= 0 ? traces[seg.fracture].joint : -1;
    if (joint < 0) joint = scene.default_joint;
    const flow::EndAperture e =
        laws.of_joint(joint).at(flow::WallEnd{0, applied[s], 0}, seg.aperture, g.length(s));
    e_a[s] = e_b[s] = e.aperture;
  }

  // 4. The deformed network's permeability (in the square's frame, as cut),
  //    before the compliance's increments move the blocks on.
  out.permeability =
      flow::domain_permeability(g, size, setup.viscosity, setup.pressure_drop, e_a, e_b);

  // 5. The tangent compliance, of the floating square (floating_compliance).
  if (setup.compliance_increment > 0) {
    scene.blocks.pop_back();  // the platen
    out.mechanics.compliance = floating_compliance(scene, setup, size, stress);
  }
  return out;
}

}  // namespace fissure

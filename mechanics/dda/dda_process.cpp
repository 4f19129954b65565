#include "mechanics/dda/dda_process.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "core/base/errors.h"
#include "core/base/memory_budget.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "core/process/exchanged_values.h"
#include "mechanics/dda/dda_settings.h"  // kMechanicsSection
#include "mechanics/dda/open_close.h"
#include "mechanics/dda/step_update.h"
#include "mechanics/dda/vibration_damping.h"
#include "rockmass/fields/block_thermal_strain.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::dda {

namespace {

// Step control (theory.md 1.7): cut factors and growth back towards g1.
constexpr double kOpenCloseCut = 0.3;
constexpr double kDisplacementSafety = 0.8;
constexpr double kGrowth = 1.3;
// The least share of its area a block may keep after a step (4b below).
constexpr double kSmallestAreaRatio = 0.5;
// Augmented Lagrangian (3b): how much a stalled pass stiffens the step's
// springs (at most to DdaParameters::stiffest_penalty: stiffer, the
// open-close iteration chatters, 257 cuts in 1,233 steps of a 100-brick
// wall at 1e4 times a penalty of 1e8), and after how many steps without an
// update they relax by as much.
constexpr double kPenaltyGrowth = 10;
constexpr int kCalmSteps = 50;
// Contact state changes below this fraction of the step's force scale are noise.
constexpr double kForceTolerance = 1e-6;
// A chattering contact is held in its state (open_close.h) only while the force
// by which that state violates the contact law stays below this fraction of
// the step's force scale: one step's lag of a force the size of the
// equilibrium residuals, not a lost slide (the cut slope's sliding blocks,
// whose chatter is 10-30 % of their Coulomb limit, are not held).
constexpr double kHoldTolerance = 1e-3;

/// Largest force of the step: contact forces of the last step, block weights
/// and point loads.
double force_scale(const RockMass& state, const std::vector<DdaContact>& contacts,
                   const BlockLoads& loads) {
  double f = 0;
  for (const PointLoad& l : loads.point_loads) f = std::max(f, l.force.norm());
  for (const DdaContact& c : contacts) f = std::max(f, std::abs(c.normal_force));
  for (const Block& b : state.blocks)
    if (!b.fixed)
      f = std::max(f, state.materials[b.material].density * b.section.area * state.gravity.norm());
  return f;
}

/// The memory of a DDA run of `scene`'s blocks, refused before it is spent
/// (issue 35): contact detection, the contacts' records, the block system
/// and its factor grow a little faster than the block count (the factor's
/// fill-in). Measured peak resident memory above the process's own, in a
/// DFN rock mass's first step: 50 kB per block at 2,316 and 8,948 blocks,
/// 69 kB at 13,880 (the 1,000-brick wall: 57 kB); 12 kB x n x log10(n) stays
/// below each (docs/performance.md, "Memory").
void check_block_system_memory(const Scene& scene) {
  if (scene.blocks.empty()) return;
  const auto n = static_cast<double>(scene.blocks.size());
  // Generated blocks carry their rock mass's location and edge joints.
  const BlockSpec& last = scene.blocks.back();
  const SourceLocation& at = last.location;
  check_memory(12e3 * n * std::log10(std::max(n, 10.0)),
               fmt::format("{}:{}:{}: {}", at.file, at.line, at.column,
                           last.edge_joint.empty() ? "blocks" : "rock_mass"),
               fmt::format("a DDA system of {} blocks", scene.blocks.size()));
}

}  // namespace

DdaProcess::DdaProcess(const Scene& scene)
    : p_(DdaParameters::from_scene(scene)), laws_(contact_laws(scene.joints)) {
  check_block_system_memory(scene);
  loads_.fixed_points = scene.fixed_points;
  loads_.point_loads = scene.point_loads;
  next_dt_ = p_.max_time_step;
  const MechanicsControls& controls = mechanics_controls(scene);
  if (const auto& g = controls.ground_motion) {
    ground_motion_ = GroundMotion(g->record, g->start, g->baseline_correction);
    driven_names_ = g->blocks;
  }
  viscous_boundaries_ = controls.viscous_boundaries;
  ejected_ = EjectedBlocks(controls.dda.ejection_speed);
}

std::vector<std::string> DdaProcess::reads() const {
  // The pressure loads when the flow writes them (theory.md 3.5), the
  // blocks' free thermal strain when a thermal process does (theory.md 4.3).
  return {std::string(block_fields::geometry), std::string(block_fields::kinematics),
          std::string(block_fields::stress),   std::string(kContacts.name),
          std::string(kPressureLoads.name),    std::string(kBlockThermalStrain.name)};
}

std::vector<std::string> DdaProcess::writes() const {
  return kMechanicsSection.provided_fields();
}

void DdaProcess::initialize(RockMass& state) {
  loads_.first_fixed_point = state.first_fixed_point;
  loads_.first_load_point = state.first_load_point;
  system_ = std::make_unique<BlockSystem>(p_, state);
  thermal_ = {};
  counters_.blocks = static_cast<long>(state.blocks.size());
  for (const Block& b : state.blocks) {
    if (b.fixed) continue;
    counters_.smallest_free_area = counters_.free_blocks == 0
                                       ? b.section.area
                                       : std::min(counters_.smallest_free_area, b.section.area);
    ++counters_.free_blocks;
  }
  contacts_ = detect_contacts(state, p_.contact_range, {}, true);
  if (p_.contact_method == ContactMethod::AugmentedLagrangian)
    give_initial_stress_forces(contacts_, state, p_.friction_coefficients);
  publish_contacts(state);
  // The blocks the ground motion moves: the named ones, else every fixed one.
  if (!ground_motion_.empty()) {
    driven_.assign(state.blocks.size(), 0);
    for (std::size_t b = 0; b < state.blocks.size(); ++b)
      driven_[b] = state.blocks[b].fixed &&
                   (!driven_names_ || std::find(driven_names_->begin(), driven_names_->end(),
                                                state.blocks[b].name) != driven_names_->end());
  }
  loads_.dashpots = find_viscous_edges(state, viscous_boundaries_, p_.plane);
  // Blocks tied to a continuum interface: held at first by the forces that
  // balance their prestress (interface_ties.h).
  ties_ = InterfaceTies::find(state);
  if (!ties_.empty()) ties_.give_first_tractions(state);
}

std::vector<ExchangedField> DdaProcess::exchanged_values(const RockMass& state) const {
  return ties_.exchanged_values(state);
}

void DdaProcess::set_exchanged_values(RockMass& state, std::span<const ExchangedField> values) {
  ties_.set_exchanged_values(state, values);
}

StepReport DdaProcess::retry(double dt, std::string reason) {
  next_dt_ = dt;
  StepReport r;
  r.status = StepReport::Status::Retry;
  r.dt_retry = dt;
  r.reason = std::move(reason);
  return r;
}

StepReport DdaProcess::advance(RockMass& state, double t, double dt) {
  // 1. Contacts of the start-of-step geometry, with their history.
  Stopwatch clock;
  std::vector<DdaContact> contacts =
      detect_contacts(state, p_.contact_range, contacts_, first_step_, &detection_);
  counters_.seconds_detection += clock.seconds();
  if (frozen_) freeze_states(contacts, *frozen_);
  begin_law_step(contacts, laws_);
  if (p_.contact_method == ContactMethod::AugmentedLagrangian)
    set_contact_targets(contacts, state, p_.velocity_carry_over, dt, p_.penetration_tolerance);
  // The driven blocks' known increment over the step, in their contacts'
  // gaps and slips (contact_springs.h), and the outcrop velocity that
  // free-field boundaries take.
  if (!ground_motion_.empty()) {
    driven_increment_.setZero();
    driven_increment_.head<2>() =
        ground_motion_.displacement(t + dt) - ground_motion_.displacement(t);
    for (DdaContact& c : contacts)
      set_prescribed_motion(c, driven(c.key.block_i) ? &driven_increment_ : nullptr,
                            driven(c.key.block_j) ? &driven_increment_ : nullptr);
    loads_.free_field_velocity = ground_motion_.velocity(t + dt);
  }

  // 2. The step's system, with the contacts' dashpots (vibration_damping.h;
  //    in static analysis every step starts at rest and nothing rings).
  clock.restart();
  if (p_.velocity_carry_over > 0)
    set_contact_damping(contacts, state, p_.normal_penalty, p_.damping_ratio, dt);
  thermal_.begin_step(state, p_.plane);
  if (first_step_ && ties_.empty())
    // The interfaces are published when the continuum initializes: a block
    // region that finds none at its own start but one now came first.
    FISSURE_CHECK(InterfaceTies::find(state).empty(), CouplingOrderError,
                  tied_before_continuum("mechanics", "its blocks lie along"));
  if (!ties_.empty()) loads_.ties = ties_.springs(state);
  system_->begin_step(state, loads_, contacts, thermal_, t + dt, dt);
  counters_.seconds_assembly_solve += clock.seconds();

  // 3. Open-close iteration (and the augmented Lagrangian's passes).
  const ContactSolve solved = solve_contacts(state, contacts, t, dt);
  if (solved.retry) return *solved.retry;

  // 4. Step size control on the largest vertex displacement.
  std::vector<Vector6> increments(state.blocks.size());
  for (std::size_t b = 0; b < state.blocks.size(); ++b)
    increments[b] = driven(static_cast<int>(b)) ? driven_increment_ : system_->increment(b);
  const double dmax = max_vertex_displacement(state, increments);
  if (dmax > p_.max_step_displacement) {
    ++counters_.cuts_displacement;
    std::ostringstream why;
    why << "a vertex moved " << dmax
        << " m in one step, more than g2 w = " << p_.max_step_displacement << " m";
    return retry(kDisplacementSafety * dt * p_.max_step_displacement / dmax, why.str());
  }

  // 4b. ... and on the blocks' strain: a block whose area the step's strain
  //     would more than halve (or turn inside out) has taken a strain no
  //     rock takes in one step; in a smaller step the contacts and the
  //     inertia hold it (a 0.1 mm sliver in a dense DFN rock mass was
  //     turned inside out by one step's strain; issue 22).
  if (const auto [worst, ratio] = smallest_area_ratio(state, increments);
      worst >= 0 && ratio < kSmallestAreaRatio) {
    ++counters_.cuts_strain;
    std::ostringstream why;
    why << "block '" << state.blocks[worst].name << "' would keep " << ratio
        << " of its area after the step";
    return retry(kOpenCloseCut * dt, why.str());
  }

  // 5. Accept: update everything, let dt grow back.
  clock.restart();
  advance_law_states(contacts, laws_);
  contacts_ = std::move(contacts);
  commit(state, increments, t + dt, dt);
  if (p_.velocity_carry_over > 0)
    ejected_.record(state, contacts_, t + dt, loads_.free_field_velocity);
  if (!ties_.empty()) ties_.give_tractions(state, loads_.ties);
  counters_.seconds_update += clock.seconds();
  counters_.max_iterations_in_a_step =
      std::max<long>(counters_.max_iterations_in_a_step, solved.iterations);
  if (!frozen_) counters_.held_contacts += solved.held;
  ++counters_.steps;
  first_step_ = false;
  if (dmax < 0.5 * p_.max_step_displacement)
    next_dt_ = std::min(p_.max_time_step, next_dt_ * kGrowth);
  return {};
}

DdaProcess::ContactSolve DdaProcess::solve_contacts(RockMass& state,
                                                    std::vector<DdaContact>& contacts, double t,
                                                    double dt) {
  Stopwatch clock;
  // The step's spring constants: the penalties, stiffened by the augmented
  // Lagrangian while its multipliers stall (3b below).
  SpringConstants k{stiffening_ * p_.normal_penalty, stiffening_ * p_.shear_penalty};
  const double scale = force_scale(state, contacts, loads_);
  const double force_tolerance = kForceTolerance * scale;
  // In static analysis the first guess, the last step's increment, also
  // predicts the contact states the iteration starts from: an open-close
  // update at the guess, which counts as no change (16 % fewer open-close
  // iterations on the 1,000-brick wall, 21 % at 10,000; docs/dda.md 2). The
  // free-motion guess of dynamic analysis predicts them badly in a ringing
  // assembly (more steps cut), so there the states of the last step stay.
  // Frozen states (the iterated coupling's) are held whatever the law asks.
  const double hold_tolerance =
      frozen_ ? std::numeric_limits<double>::infinity() : kHoldTolerance * scale;
  if (!frozen_ && p_.velocity_carry_over == 0) {
    update_contact_states(contacts, system_->slots(), system_->solution(), k, force_tolerance,
                          hold_tolerance, p_.friction_coefficients, state);
    for (DdaContact& c : contacts) c.state_changes = 0;
  }
  OpenCloseResult oc;
  bool converged = false;
  int iteration = 0, pass_iterations = 0, augmentations = 0;
  double last_error = std::numeric_limits<double>::infinity();
  struct Pass {
    std::vector<DdaContact> contacts;
    Eigen::VectorXd solution;
  } last_converged;  // the augmented Lagrangian's last converged pass
  for (;;) {
    while (!converged && pass_iterations < p_.max_open_close_iterations) {
      ++iteration;
      ++pass_iterations;
      clock.restart();
      const Eigen::VectorXd* solved = nullptr;
      try {
        solved = &system_->assemble_and_solve(contacts, k);
      } catch (const SolverError& e) {
        // An ill-conditioned system (a block held by nothing but its inertia,
        // 2 M / dt^2, which vanishes with a long static step) is better
        // conditioned in a shorter step: cut it as for open-close.
        counters_.seconds_assembly_solve += clock.seconds();
        ++counters_.cuts_solver;
        return {iteration, oc.held,
                retry(kOpenCloseCut * dt, std::string("the linear solver failed: ") + e.what())};
      }
      const Eigen::VectorXd& x = *solved;
      counters_.seconds_assembly_solve += clock.seconds();
      FISSURE_CHECK(x.allFinite(), DivergenceError,
                    "non-finite displacement increments at t = "
                        << t << " s (dt = " << dt
                        << " s): the block system is singular or a parameter is non-physical");
      clock.restart();
      oc = update_contact_states(contacts, system_->slots(), x, k, force_tolerance, hold_tolerance,
                                 p_.friction_coefficients, state);
      counters_.seconds_open_close += clock.seconds();
      converged = oc.state_changes == 0;
    }
    // 3b. Augmented Lagrangian contacts: the multipliers take the forces of
    //     the converged iterate and the step is solved again, until every
    //     closed contact's gap and stuck slip are within the tolerance of
    //     their targets (open_close.h). A pass shrinks the error by about
    //     K / (K + p), K the stiffness the blocks offer at the contact (their
    //     inertia 2 M / dt^2 in dynamics, 2.7e11 N/m for a 1,350 kg block at
    //     0.1 ms against a penalty of 1e8: 0.9996 a pass); when a pass has not
    //     halved it, the step's springs are made ten times stiffer (the method
    //     of multipliers with a growing penalty, Bertsekas 1982), so that a
    //     few passes reach any tolerance whatever the scene's penalty.
    if (!converged && augmentations > 0) {
      // A pass whose open-close iteration no longer converges (stiffer
      // springs chatter more) does not cut the step: the last converged
      // pass is taken, as a penalty solution.
      contacts = std::move(last_converged.contacts);
      system_->set_solution(last_converged.solution);
      converged = true;
      ++counters_.augmentation_fallbacks;
      break;
    }
    if (!converged || p_.contact_method != ContactMethod::AugmentedLagrangian) break;
    const double error = largest_contact_error(contacts);
    if (error <= 1) break;  // within every contact's tolerance
    if (augmentations == p_.max_augmentations) {
      ++counters_.augmentation_limit;  // a penalty solution, accepted as such
      break;
    }
    last_converged = {contacts, system_->solution()};
    update_multipliers(contacts, k, p_.friction_coefficients, state.joints);
    if (error > 0.5 * last_error && stiffening_ * p_.normal_penalty < p_.stiffest_penalty) {
      stiffening_ = std::min(stiffening_ * kPenaltyGrowth, p_.stiffest_penalty / p_.normal_penalty);
      k = {stiffening_ * p_.normal_penalty, stiffening_ * p_.shear_penalty};
      ++counters_.penalty_growths;
    }
    last_error = error;
    ++augmentations;
    converged = false;
    pass_iterations = 0;
  }
  counters_.open_close_iterations += iteration;
  counters_.augmentations += augmentations;
  // The stiffening carries over to the next step (the blocks' inertia, what
  // it answers, changes slowly), and relaxes by the growth factor after
  // kCalmSteps steps that needed no update: the springs stay no stiffer than
  // they must, without a new factorization in every step (each change of
  // the springs is one: relaxing after every calm step, the 100-brick wall
  // grew and relaxed 862 times in 1,355 steps).
  calm_steps_ = augmentations == 0 ? calm_steps_ + 1 : 0;
  if (calm_steps_ >= kCalmSteps && stiffening_ > 1) {
    stiffening_ = std::max(1.0, stiffening_ / kPenaltyGrowth);
    calm_steps_ = 0;
  }
  counters_.max_augmentations_in_a_step =
      std::max<long>(counters_.max_augmentations_in_a_step, augmentations);
  if (!converged) {
    ++counters_.cuts_open_close;
    std::ostringstream why;
    why << "open-close iteration did not converge in " << iteration << " iterations ("
        << oc.state_changes << " contacts still changing state)";
    return {iteration, oc.held, retry(kOpenCloseCut * dt, why.str())};
  }
  return {iteration, oc.held, std::nullopt};
}

void DdaProcess::commit(RockMass& state, const std::vector<Vector6>& increments, double t_end,
                        double dt) {
  // Material points first: they move with their block's start-of-step centroid.
  for (std::size_t n = 0; n < state.points.size(); ++n) {
    MaterialPoint& mp = state.points[n];
    if (mp.block < 0 || (state.blocks[mp.block].fixed && !driven(mp.block))) continue;
    const Vec2 moved = moved_point(mp.current, state.blocks[mp.block].section.centroid,
                                   increments[mp.block], p_.exact_rotation);
    const int load = static_cast<int>(n) - loads_.first_load_point;
    if (load >= 0 && load < static_cast<int>(loads_.point_loads.size())) {
      const PointLoad& l = loads_.point_loads[load];
      ledger_.add_load_work(load_factor(l, t_end) * l.force.dot(moved - mp.current));
    }
    mp.current = moved;
  }
  // The viscous boundaries' work, on the start-of-step geometry.
  if (!loads_.dashpots.empty()) {
    double work = 0;
    for (const ViscousEdge& e : loads_.dashpots) {
      const Block& block = state.blocks[e.block];
      const Vector6 end_velocity =
          (2 / dt) * increments[e.block] - p_.velocity_carry_over * block.velocity;
      work += viscous_work(e, block, end_velocity, increments[e.block],
                           e.free_field ? loads_.free_field_velocity : Vec2::Zero());
    }
    ledger_.add_boundary_work(work);
  }
  for (std::size_t b = 0; b < state.blocks.size(); ++b) {
    Block& block = state.blocks[b];
    if (driven(static_cast<int>(b))) {  // moved as the record says, rigidly
      update_block(block, increments[b], dt, 0.0, Eigen::Matrix3d::Zero(), p_.exact_rotation);
      block.velocity.setZero();
      block.velocity.head<2>() = loads_.free_field_velocity;  // the record's at t_end
    }
    if (block.fixed) continue;
    const Eigen::Matrix3d elastic = elastic_matrix(state.materials[block.material], p_.plane);
    Eigen::Vector3d thermal_strain;  // the step's, when it has a thermal strain field
    if (thermal_.active()) {
      thermal_strain = thermal_.step_strain(static_cast<int>(b));
      ledger_.add_thermal_work(block.section.area, block.stress, elastic, thermal_strain);
    }
    update_block(block, increments[b], dt, p_.velocity_carry_over, elastic, p_.exact_rotation,
                 thermal_.active() ? &thermal_strain : nullptr);
    FISSURE_CHECK(block.section.area > 0 && std::isfinite(block.section.area), DivergenceError,
                  "block '" << block.name << "' turned inside out at t = " << t_end << " s (area "
                            << block.section.area << "): the strain increment is non-physical");
  }
  thermal_.commit();
  ledger_.add_friction(contacts_, p_.shear_penalty);
  if (!ground_motion_.empty()) ledger_.add_base_work(contacts_);
  for (const DdaContact& c : contacts_)
    if (c.state != ContactState::Open)
      counters_.max_penetration = std::max(counters_.max_penetration, -c.gap);
  publish_contacts(state);
}

void DdaProcess::publish_contacts(RockMass& state) const {
  std::vector<ContactRecord>& records = state.fields.get_or_add(kContacts);
  records.clear();
  records.reserve(contacts_.size());
  for (const DdaContact& c : contacts_) {
    const Polygon& pj = state.blocks[c.key.block_j].polygon;
    const Vec2 a = pj.vertices[c.key.edge], b = pj.vertices[pj.next(c.key.edge)];
    ContactRecord r;
    r.block_i = c.key.block_i;
    r.block_j = c.key.block_j;
    r.vertex = c.key.vertex;
    r.edge = c.key.edge;
    r.point = state.blocks[c.key.block_i].polygon.vertices[c.key.vertex];
    r.normal = Vec2(b.y() - a.y(), a.x() - b.x()).normalized();
    r.state = c.state;
    r.gap = c.gap;
    r.normal_force = c.normal_force;
    r.shear_force = c.shear_force;
    records.push_back(r);
  }
}

nlohmann::json DdaProcess::statistics() const {
  long open = 0, sliding = 0, locked = 0;
  for (const DdaContact& c : contacts_) {
    if (c.state == ContactState::Open) ++open;
    if (c.state == ContactState::Sliding) ++sliding;
    if (c.state == ContactState::Locked) ++locked;
  }
  nlohmann::json s = {
      {"method", "dda"},
      {"steps", counters_.steps},
      {"open_close_iterations", counters_.open_close_iterations},
      {"max_open_close_iterations_in_a_step", counters_.max_iterations_in_a_step},
      {"held_contacts", counters_.held_contacts},
      {"contact_method", name_of(kContactMethodNames, p_.contact_method)},
      {"blocks",
       {{"total", counters_.blocks},
        {"free", counters_.free_blocks},
        {"smallest_free_area", counters_.smallest_free_area}}},
      {"time_step_cuts",
       {{"open_close", counters_.cuts_open_close},
        {"displacement_ratio", counters_.cuts_displacement},
        {"linear_solver", counters_.cuts_solver},
        {"strain", counters_.cuts_strain}}},
      {"contacts", {{"open", open}, {"sliding", sliding}, {"locked", locked}}},
      {"contact_pairs_tested",
       {{"vertex_edge", detection_.vertex_edge}, {"vertex_vertex", detection_.vertex_vertex}}},
      {"max_penetration", counters_.max_penetration},
      {"penalty",
       {{"normal", p_.normal_penalty},
        {"shear", p_.shear_penalty},
        {"fixed_point", p_.fixed_point_penalty}}},
      {"max_step_displacement", p_.max_step_displacement},
      {"contact_range", p_.contact_range},
      {"seconds",
       {{"contact_detection", counters_.seconds_detection},
        {"assembly", counters_.seconds_assembly_solve - (system_ ? system_->solve_seconds() : 0)},
        {"solve", system_ ? system_->solve_seconds() : 0.0},
        {"open_close", counters_.seconds_open_close},
        {"update", counters_.seconds_update}}},
      {"linear_solver", system_ ? system_->statistics() : nlohmann::json()},
  };
  if (!ground_motion_.empty()) {
    s["ground_motion"] = ground_motion_.report();
    long blocks = 0;
    for (const char d : driven_) blocks += d;
    s["ground_motion"]["driven_blocks"] = blocks;
  }
  if (p_.contact_method == ContactMethod::AugmentedLagrangian)
    s["augmented_lagrangian"] = {
        {"penetration_tolerance", p_.penetration_tolerance},
        {"augmentations", counters_.augmentations},
        {"max_augmentations_in_a_step", counters_.max_augmentations_in_a_step},
        {"steps_at_the_limit", counters_.augmentation_limit},
        {"penalty_growths", counters_.penalty_growths},
        {"fallbacks", counters_.augmentation_fallbacks}};
  if (p_.velocity_carry_over > 0) s["ejected_blocks"] = ejected_.report();
  if (!viscous_boundaries_.empty())
    s["viscous_boundaries"] = {{"lines", viscous_boundaries_.size()},
                               {"edges", loads_.dashpots.size()}};
  return s;
}

template <class Self, class Archive>
void DdaProcess::checkpoint(Self& self, Archive& a) {
  a("next_dt", self.next_dt_);
  a("spring_stiffening", self.stiffening_);
  a("calm_steps", self.calm_steps_);
  a("first_step", self.first_step_);
  a.list("contacts", self.contacts_, [](auto& e, auto& c) { checkpoint_fields(e, c); });
  // The law states of the contacts that have one (checkpoint_fields wrote which), in order.
  std::vector<joints::JointLaw::State> law_states;
  if constexpr (!Archive::reading)
    for (const DdaContact& contact : self.contacts_)
      if (contact.law) law_states.push_back(*contact.law);
  auto laws = a.section("contact_law_states");
  joints::checkpoint_law_states(laws, law_states);
  if constexpr (Archive::reading) {
    std::size_t next = 0;
    for (DdaContact& contact : self.contacts_) {
      if (!contact.law) continue;
      FISSURE_CHECK(next < law_states.size(), IoError,
                    "checkpoint: fewer contact law states than contacts with a law");
      contact.law = law_states[next++];
    }
    FISSURE_CHECK(next == law_states.size(), IoError,
                  "checkpoint: more contact law states than contacts with a law");
  }
  auto ledger = a.section("energy");
  EnergyLedger::checkpoint(self.ledger_, ledger);
  ThermalStrain::checkpoint(self.thermal_, a);
  auto ejected = a.section("ejected_blocks");
  EjectedBlocks::checkpoint(self.ejected_, ejected);
  auto c = a.section("counters");
  auto& n = self.counters_;  // const when writing
  c("steps", n.steps);
  c("open_close_iterations", n.open_close_iterations);
  c("max_iterations_in_a_step", n.max_iterations_in_a_step);
  c("cuts_open_close", n.cuts_open_close);
  c("cuts_displacement", n.cuts_displacement);
  c("cuts_solver", n.cuts_solver);
  c("cuts_strain", n.cuts_strain);
  c("held_contacts", n.held_contacts);
  // The augmented Lagrangian's counts: only a scene that uses it stores them.
  if (self.p_.contact_method == ContactMethod::AugmentedLagrangian) {
    c("augmentations", n.augmentations);
    c("max_augmentations_in_a_step", n.max_augmentations_in_a_step);
    c("augmentation_limit", n.augmentation_limit);
    c("penalty_growths", n.penalty_growths);
    c("augmentation_fallbacks", n.augmentation_fallbacks);
  }
  c("max_penetration", n.max_penetration);
  c("seconds_detection", n.seconds_detection);
  c("seconds_assembly_solve", n.seconds_assembly_solve);
  c("seconds_open_close", n.seconds_open_close);
  c("seconds_update", n.seconds_update);
  c("detection_vertex_edge", self.detection_.vertex_edge);
  c("detection_vertex_vertex", self.detection_.vertex_vertex);
}

void DdaProcess::freeze_discrete_states(bool on) {
  if (on)
    frozen_ = contacts_;
  else
    frozen_.reset();
}

void DdaProcess::save(CheckpointWriter& out, const RockMass& state) const {
  checkpoint(*this, out);
  auto system = out.section("block_system");
  system_->save(system);
  if (!ties_.empty())  // the tractions its blocks give the continuum
    out("interface_tractions", ties_.mortar().values(state));
}

void DdaProcess::restore(CheckpointReader& in, RockMass& state) {
  checkpoint(*this, in);
  auto system = in.section("block_system");
  system_->restore(system);
  publish_contacts(state);
  if (!ties_.empty()) {
    std::vector<double> tractions;
    in("interface_tractions", tractions);
    ties_.mortar().set_values(state, tractions);
  }
}

nlohmann::json DdaProcess::energy(const RockMass& state) const {
  return ledger_.evaluate(state, contacts_, p_, loads_).to_json();
}

}  // namespace fissure::dda

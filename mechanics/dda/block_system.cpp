#include "mechanics/dda/block_system.h"

#include <algorithm>

#include "core/base/errors.h"
#include "core/base/stopwatch.h"
#include "core/io/checkpoint.h"
#include "mechanics/dda/block_kinematics.h"
#include "mechanics/dda/vibration_damping.h"
#include "rockmass/fields/pressure_loads.h"

namespace fissure::dda {

double load_factor(const PointLoad& load, double t) {
  return history_factor(load.history, t);
}

BlockSystem::BlockSystem(const DdaParameters& parameters, const RockMass& state)
    : p_(parameters), solver_(make_block_solver(parameters.solver)) {
  for (const Material& m : state.materials) elastic_.push_back(elastic_matrix(m, p_.plane));
}

void BlockSystem::add_fixed_point(const FixedPoint& f, const Vec2& current, const Block& b,
                                  Matrix6& k, Vector6& rhs) const {
  // Penalty spring towards the point's original position (theory.md 1.3 with
  // u_bar = anchor - current), so that a held point does not drift step by step.
  const Matrix26 t = displacement_matrix(current, b.section.centroid);
  const Vec2 back = f.point - current;
  for (int axis = 0; axis < 2; ++axis) {
    if ((axis == 0 && !f.fix_x) || (axis == 1 && !f.fix_y)) continue;
    const Vector6 row = t.row(axis).transpose();
    k.noalias() += p_.fixed_point_penalty * row * row.transpose();
    rhs += p_.fixed_point_penalty * back(axis) * row;
  }
}

void BlockSystem::add_tie(const TieSpring& s, const Vec2& current, const Block& b, Matrix6& k,
                          Vector6& rhs) {
  const Matrix26 t = displacement_matrix(current, b.section.centroid);
  k.noalias() += s.stiffness * t.transpose() * t;
  rhs.noalias() += t.transpose() * (s.force + s.stiffness * (s.target - current));
}

void BlockSystem::begin_step(const RockMass& state, const BlockLoads& loads,
                             const std::vector<DdaContact>& contacts, const ThermalStrain& thermal,
                             double t_end, double dt) {
  const int n = static_cast<int>(state.blocks.size());
  // 1. Unknowns only for free blocks.
  dof_.assign(n, -1);
  n_free_ = 0;
  for (int b = 0; b < n; ++b)
    if (!state.blocks[b].fixed) dof_[b] = n_free_++;

  // 2. Per-block terms: inertia (Newmark beta = 1/2, gamma = 1), elasticity,
  //    initial stress, the step's thermal strain, body force.
  base_matrix_.assign(n_free_, Matrix6::Zero());
  base_rhs_.assign(n_free_, Vector6::Zero());
  for (int b = 0; b < n; ++b) {
    if (dof_[b] < 0) continue;
    const Block& block = state.blocks[b];
    const Material& mat = state.materials[block.material];
    const double area = block.section.area;
    const double density = current_density(block, mat.density);
    const Matrix6 mass = mass_matrix(density, block.section);
    Matrix6& k = base_matrix_[dof_[b]];
    Vector6& f = base_rhs_[dof_[b]];
    k = (2 / (dt * dt)) * mass;
    const Eigen::Matrix3d stiffness = area * elastic_[block.material];
    // Viscous stress b E de/dt over the step (vibration_damping.h); in static
    // analysis (k01 = 0) every step starts at rest and nothing rings.
    // From the current state, every step (a 3 x 3 eigenproblem), so that a
    // run restarted from a checkpoint continues to the same bits.
    const double strain_viscous_time =
        p_.velocity_carry_over > 0 && p_.damping_ratio > 0
            ? viscous_time(lowest_strain_frequency(mass, stiffness), p_.damping_ratio, dt)
            : 0.0;
    k.block<3, 3>(3, 3) += (1 + strain_viscous_time / dt) * stiffness;
    f = (2 / dt) * mass * (p_.velocity_carry_over * block.velocity);
    f.segment<3>(3) -= area * block.stress;
    // Initial strain (theory.md 1.3, 4.3): F += S E d_eps*, the step's part.
    if (thermal.active())
      f.segment<3>(3) += area * elastic_[block.material] * thermal.step_strain(b);
    f(0) += density * area * state.gravity.x();
    f(1) += density * area * state.gravity.y();
  }
  // 3. Point loads (at the end of the step) and fixed points, at their material points.
  for (std::size_t l = 0; l < loads.point_loads.size(); ++l) {
    const PointLoad& load = loads.point_loads[l];
    const int d = dof_[load.block];
    if (d < 0) continue;
    const Vec2& x = state.points[loads.first_load_point + l].current;
    base_rhs_[d] += displacement_matrix_transpose_times(
        x, state.blocks[load.block].section.centroid, load_factor(load, t_end) * load.force);
  }
  for (std::size_t f = 0; f < loads.fixed_points.size(); ++f) {
    const FixedPoint& fp = loads.fixed_points[f];
    const int d = dof_[fp.block];
    if (d < 0) continue;
    add_fixed_point(fp, state.points[loads.first_fixed_point + f].current, state.blocks[fp.block],
                    base_matrix_[d], base_rhs_[d]);
  }
  for (const TieSpring& s : loads.ties) {
    const int d = dof_[s.block];
    if (d < 0) continue;
    add_tie(s, s.position(state), state.blocks[s.block], base_matrix_[d], base_rhs_[d]);
  }
  for (const ViscousEdge& e : loads.dashpots) {
    const int d = dof_[e.block];
    if (d < 0) continue;
    const Block& b = state.blocks[e.block];
    add_viscous_edge(e, b, p_.velocity_carry_over * b.velocity,
                     e.free_field ? loads.free_field_velocity : Vec2::Zero(), dt, base_matrix_[d],
                     base_rhs_[d]);
  }

  // 3b. Fluid pressure on block edges, written by the flow process
  //     (theory.md 3.5): F += -L/6 [(2 pa + pb) T(a)^T + (pa + 2 pb) T(b)^T] n.
  if (const std::vector<EdgePressureLoad>* edge_loads = state.fields.find(kPressureLoads)) {
    for (const EdgePressureLoad& e : *edge_loads) {
      const int d = dof_[e.block];
      if (d < 0) continue;
      const double w = (e.b - e.a).norm() / 6;
      const Vec2& c = state.blocks[e.block].section.centroid;
      base_rhs_[d] +=
          displacement_matrix_transpose_times(e.a, c, -w * (2 * e.p_a + e.p_b) * e.normal) +
          displacement_matrix_transpose_times(e.b, c, -w * (e.p_a + 2 * e.p_b) * e.normal);
      if (e.has_shear())  // + the shear traction along the edge, alike
        base_rhs_[d] +=
            displacement_matrix_transpose_times(e.a, c, w * (2 * e.s_a + e.s_b) * e.tangent()) +
            displacement_matrix_transpose_times(e.b, c, w * (e.s_a + 2 * e.s_b) * e.tangent());
    }
  }

  // 4. Pattern: one off-diagonal block per pair of free blocks in contact range.
  pairs_.clear();
  for (const DdaContact& c : contacts) {
    const int i = dof_[c.key.block_i], j = dof_[c.key.block_j];
    if (i >= 0 && j >= 0) pairs_.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(pairs_.begin(), pairs_.end());
  pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
  const bool same_pattern = analysed_ && pairs_ == analysed_pairs_ && matrix_.n_blocks() == n_free_;
  if (!same_pattern) matrix_.set_pattern(n_free_, pairs_);

  slots_.resize(contacts.size());
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    ContactSlots& s = slots_[c];
    s.dof_i = dof_[contacts[c].key.block_i];
    s.dof_j = dof_[contacts[c].key.block_j];
    s.ii = s.dof_i >= 0 ? matrix_.diagonal_index(s.dof_i) : -1;
    s.jj = s.dof_j >= 0 ? matrix_.diagonal_index(s.dof_j) : -1;
    s.ij = s.dof_i >= 0 && s.dof_j >= 0 ? matrix_.find(s.dof_i, s.dof_j) : -1;
    s.ji = s.dof_i >= 0 && s.dof_j >= 0 ? matrix_.find(s.dof_j, s.dof_i) : -1;
  }
  factored_.contacts_replaced();  // a new contact list, matched again
  if (!same_pattern) {
    // Analyse once per pattern with representative values.
    for (int b = 0; b < n_free_; ++b) matrix_.value(matrix_.diagonal_index(b)) = base_matrix_[b];
    const Stopwatch clock;
    solver_->analyze(matrix_);
    solve_seconds_ += clock.seconds();
    analysed_pairs_ = pairs_;
    analysed_diagonal_.assign(base_matrix_.begin(), base_matrix_.begin() + n_free_);
    analysed_ = true;
  }
  // First guess for iterative solvers; later iterates start from the last.
  // Dynamic: free motion with the start velocity (exact for a block without
  // forces). Static (k01 = 0, every step starts at rest): the last step's
  // increment d, scaled to this dt (the block keeps v = 2 d / dt_last), which
  // a creeping assembly repeats; on the settled 1,000-brick wall GMRES then
  // needs ~10 % fewer iterations than from zero (docs/performance-history.md).
  const double guess = p_.velocity_carry_over > 0 ? dt * p_.velocity_carry_over : dt / 2;
  solution_.resize(6 * n_free_);
  for (int b = 0; b < n; ++b)
    if (dof_[b] >= 0) solution_.segment<6>(6 * dof_[b]) = guess * state.blocks[b].velocity;
}

const Eigen::VectorXd& BlockSystem::assemble_and_solve(const std::vector<DdaContact>& contacts,
                                                       const SpringConstants& k) {
  matrix_.set_zero();
  rhs_.resize(6 * n_free_);
  for (int b = 0; b < n_free_; ++b) {
    matrix_.value(matrix_.diagonal_index(b)) = base_matrix_[b];
    rhs_.segment<6>(6 * b) = base_rhs_[b];
  }
  // Sliding friction makes A unsymmetric (contact_springs.h).
  bool friction = false;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const double mu = friction_coefficient(contacts[c], p_.friction_coefficients);
    assemble_contact_springs(contacts[c], slots_[c], k, matrix_, rhs_);
    assemble_sliding_friction(contacts[c], slots_[c], k.normal, mu, matrix_, rhs_);
    friction |= contacts[c].state == ContactState::Sliding && mu > 0;
  }
  describe_change(contacts, k);
  const Stopwatch clock;
  if (n_free_ > 0) solver_->solve(matrix_, !friction, rhs_, solution_);
  if (solver_->factorized()) {
    factored_.record(contacts, slots_);
    factored_springs_ = k;
  }
  solve_seconds_ += clock.seconds();
  return solution_;
}

void BlockSystem::describe_change(const std::vector<DdaContact>& contacts,
                                  const SpringConstants& k) {
  const int max_terms = solver_->max_update_terms();
  if (max_terms == 0) return;
  // A factor of other spring constants differs in every closed contact.
  const bool known =
      !factored_.empty() && factored_springs_.normal == k.normal &&
      factored_springs_.shear == k.shear &&
      factored_.describe(contacts, slots_, k, p_.friction_coefficients, max_terms, update_);
  solver_->expect(known ? &update_ : nullptr);
}

Vector6 BlockSystem::increment(int block) const {
  const int d = dof_[block];
  return d >= 0 ? Vector6(solution_.segment<6>(6 * d)) : Vector6::Zero();
}

template <class Self, class Archive>
void BlockSystem::checkpoint(Self& self, Archive& a) {
  auto factored = a.section("factored_contacts");
  FactoredContacts::checkpoint(self.factored_, factored);
  a("factored_normal_spring", self.factored_springs_.normal);
  a("factored_shear_spring", self.factored_springs_.shear);
  a("analysed", self.analysed_);
  a("analysed_blocks", self.n_free_);
  a.list("analysed_pairs", self.analysed_pairs_, [](auto& e, auto& p) {
    e("i", p.first);
    e("j", p.second);
  });
  a("analysed_diagonal", self.analysed_diagonal_);
  a("solve_seconds", self.solve_seconds_);
}

void BlockSystem::save(CheckpointWriter& out) const {
  checkpoint(*this, out);
  auto solver = out.section("solver");
  solver_->save(solver);
}

void BlockSystem::restore(CheckpointReader& in) {
  checkpoint(*this, in);
  // The pattern is analysed again as it was (with the same values); then
  // the solver restores its factor and its counters.
  if (analysed_) {
    matrix_.set_pattern(n_free_, analysed_pairs_);
    for (int b = 0; b < n_free_; ++b)
      matrix_.value(matrix_.diagonal_index(b)) = analysed_diagonal_[b];
    solver_->analyze(matrix_);
  }
  auto solver = in.section("solver");
  solver_->restore(solver);
}

nlohmann::json BlockSystem::statistics() const {
  nlohmann::json s = solver_->statistics();
  s["name"] = solver_->name();
  s["seconds"] = solve_seconds_;
  return s;
}

}  // namespace fissure::dda

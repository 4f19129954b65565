#include "mechanics/dda/contact_springs.h"

#include <algorithm>
#include <cmath>

namespace fissure::dda {

namespace {

// Adjacent edges within this angle of the contact edge count as lying on it.
constexpr double kParallelSine = 0.09;  // ~5 degrees

struct ContactPoints {
  Vec2 p1, p2, p3;
  Vec2 ci, cj;  // block centroids
};

ContactPoints points_of(const DdaContact& c, const RockMass& state) {
  const Block& bi = state.blocks[c.key.block_i];
  const Block& bj = state.blocks[c.key.block_j];
  const Polygon& pj = bj.polygon;
  return {bi.polygon.vertices[c.key.vertex], pj.vertices[pj.next(c.key.edge)],
          pj.vertices[c.key.edge], bi.section.centroid, bj.section.centroid};
}

/// Half the length of the contact edge covered by the vertex's own edges that
/// lie along it: the share of joint length the contact represents (so that the
/// contacts at both ends of an edge-to-edge overlap add up to the overlap).
double tributary_length(const DdaContact& c, const RockMass& state, const ContactPoints& x) {
  const Polygon& pi = state.blocks[c.key.block_i].polygon;
  const Vec2 t = (x.p3 - x.p2) / c.length;
  const auto clip = [](double s) { return std::clamp(s, 0.0, 1.0); };
  double covered = 0;
  for (const int r : {pi.next(c.key.vertex), pi.prev(c.key.vertex)}) {
    const Vec2 along = pi.vertices[r] - x.p1;
    if (std::abs(cross(along, t)) > kParallelSine * along.norm()) continue;
    const double s_r = (pi.vertices[r] - x.p2).dot(t) / c.length;
    covered += std::abs(clip(s_r) - clip(c.t_start)) * c.length;
  }
  return covered / 2;
}

}  // namespace

void prepare_contact(DdaContact& c, const RockMass& state) {
  const ContactPoints x = points_of(c, state);
  const Vec2 edge = x.p3 - x.p2;
  c.length = edge.norm();
  const double l = c.length;
  c.t_start = (x.p1 - x.p2).dot(edge) / (l * l);
  c.gap0 = cross(x.p2 - x.p1, x.p3 - x.p1) / l;
  c.e = displacement_matrix_transpose_times(x.p1, x.ci,
                                            Vec2(x.p2.y() - x.p3.y(), x.p3.x() - x.p2.x())) /
        l;
  c.g = (displacement_matrix_transpose_times(x.p2, x.cj,
                                             Vec2(x.p3.y() - x.p1.y(), x.p1.x() - x.p3.x())) +
         displacement_matrix_transpose_times(x.p3, x.cj,
                                             Vec2(x.p1.y() - x.p2.y(), x.p2.x() - x.p1.x()))) /
        l;
  c.tributary_length = tributary_length(c, state, x);

  // Slip from P0 (theory.md 1.4 with P0 the projection): the edge-rotation
  // term (T_j(P3) - T_j(P2))^T (P1 - P0) is kept; it vanishes while P1 lies on
  // the edge line.
  const Vec2 p0 = x.p2 + c.t_start * edge;
  const Vec2 t_hat = edge / l;
  c.es = displacement_matrix_transpose_times(x.p1, x.ci, edge) / l;
  c.gs = (-displacement_matrix_transpose_times(p0, x.cj, edge) +
          displacement_matrix_transpose_times(x.p3, x.cj, x.p1 - p0) -
          displacement_matrix_transpose_times(x.p2, x.cj, x.p1 - p0)) /
         l;
  c.friction_i = displacement_matrix_transpose_times(x.p1, x.ci, t_hat);
  c.friction_j = displacement_matrix_transpose_times(p0, x.cj, t_hat);
  c.shear_force_start = c.state == ContactState::Open ? 0.0 : c.shear_force;
  c.shear_anchor = c.shear_force_start;
  c.state_changes = 0;
}

namespace {

/// Spring k (a + e.Di + g.Dj)^2 / 2 into the system.
void add_spring(double k, double a, const Vector6& e, const Vector6& g, const ContactSlots& s,
                BlockSparseMatrix& m, Eigen::VectorXd& rhs) {
  if (s.dof_i >= 0) {
    m.value(s.ii).noalias() += k * e * e.transpose();
    rhs.segment<6>(6 * s.dof_i) -= k * a * e;
  }
  if (s.dof_j >= 0) {
    m.value(s.jj).noalias() += k * g * g.transpose();
    rhs.segment<6>(6 * s.dof_j) -= k * a * g;
  }
  if (s.dof_i >= 0 && s.dof_j >= 0) m.add_pair(s.ij, s.ji, k * e * g.transpose());
}

}  // namespace

void assemble_contact_springs(const DdaContact& c, const ContactSlots& s, const SpringConstants& k,
                              BlockSparseMatrix& matrix, Eigen::VectorXd& rhs) {
  if (c.state == ContactState::Open) return;
  // Spring k f (a / f + D): the spring's force k (a + D) plus the dashpot's
  // (f - 1) k D over the step.
  // A driven block's prescribed motion is part of the increment.
  // The multiplier lambda is a force the spring adds to: k (d - lambda / k).
  const double f = c.spring_factor;
  add_spring(k.normal * f, (c.gap0 - c.normal_multiplier / k.normal) / f + c.prescribed_gap, c.e,
             c.g, s, matrix, rhs);
  if (c.state == ContactState::Locked)
    add_spring(k.shear * f, c.shear_anchor / (k.shear * f) + c.prescribed_slip, c.es, c.gs, s,
               matrix, rhs);
}

void assemble_sliding_friction(const DdaContact& c, const ContactSlots& s, double normal_penalty,
                               double friction_coefficient, BlockSparseMatrix& matrix,
                               Eigen::VectorXd& rhs) {
  if (c.state != ContactState::Sliding) return;
  // Force -s mu N along t_hat on P1 (block i) and +s mu N on P0 (block j),
  // with N = -p_n (gap0 + e.Di + g.Dj). Moving the D terms to the left-hand
  // side gives the unsymmetric blocks.
  const double f = c.slip_sign * friction_coefficient * normal_penalty;  // force = f * d on i
  const double gap0 = c.gap0 + c.prescribed_gap - c.normal_multiplier / normal_penalty;
  if (s.dof_i >= 0) {
    rhs.segment<6>(6 * s.dof_i) += f * gap0 * c.friction_i;
    matrix.add(s.ii, -f * c.friction_i * c.e.transpose());
    if (s.dof_j >= 0) matrix.add(s.ij, -f * c.friction_i * c.g.transpose());
  }
  if (s.dof_j >= 0) {
    rhs.segment<6>(6 * s.dof_j) -= f * gap0 * c.friction_j;
    matrix.add(s.jj, f * c.friction_j * c.g.transpose());
    if (s.dof_i >= 0) matrix.add(s.ji, f * c.friction_j * c.e.transpose());
  }
}

namespace {

Vector12 stack(const Vector6& a, const Vector6& b) {
  Vector12 v;
  v.head<6>() = a;
  v.tail<6>() = b;
  return v;
}

/// The rank-one terms the contact puts into the system, times `sign`.
void contact_terms(const DdaContact& c, const ContactSlots& s, const SpringConstants& k,
                   double friction_coefficient, double sign, LowRankUpdate& terms) {
  if (c.state == ContactState::Open) return;
  const Vector12 normal = stack(c.e, c.g);
  Vector12 u = k.normal * c.spring_factor * normal;
  if (c.state == ContactState::Sliding)
    u += c.slip_sign * friction_coefficient * k.normal * stack(-c.friction_i, c.friction_j);
  terms.push_back({s.dof_i, s.dof_j, sign * u, normal});
  if (c.state == ContactState::Locked) {
    const Vector12 shear = stack(c.es, c.gs);
    terms.push_back({s.dof_i, s.dof_j, sign * k.shear * c.spring_factor * shear, shear});
  }
}

}  // namespace

void set_prescribed_motion(DdaContact& c, const Vector6* d_i, const Vector6* d_j) {
  c.prescribed_gap = (d_i ? c.e.dot(*d_i) : 0.0) + (d_j ? c.g.dot(*d_j) : 0.0);
  c.prescribed_slip = (d_i ? c.es.dot(*d_i) : 0.0) + (d_j ? c.gs.dot(*d_j) : 0.0);
}

void add_change_terms(const DdaContact& now, const ContactSlots& now_slots,
                      const DdaContact* before, const ContactSlots& before_slots,
                      const SpringConstants& k, double now_friction, double before_friction,
                      LowRankUpdate& terms) {
  LowRankUpdate own;
  contact_terms(now, now_slots, k, now_friction, 1.0, own);
  if (before) contact_terms(*before, before_slots, k, before_friction, -1.0, own);
  for (std::size_t a = 0; a < own.size(); ++a) {
    for (std::size_t b = a + 1; b < own.size(); ++b)
      if (own[b].v == own[a].v && own[b].block_i == own[a].block_i &&
          own[b].block_j == own[a].block_j) {
        own[a].u += own[b].u;
        own[b].u.setZero();
      }
    if (!own[a].u.isZero(0)) terms.push_back(own[a]);
  }
}

}  // namespace fissure::dda

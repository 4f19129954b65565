#include "continuum/poroelasticity/continuum_constraints.h"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <numbers>

#include "core/base/errors.h"

namespace fissure::continuum {

namespace {

using Type = ContinuumCondition::Type;
using Triplets = std::vector<Eigen::Triplet<double>>;

/// Finishes a numbering whose prescribed entries are marked (condition >= 0)
/// and whose tied entries share a group id (>= 0): numbers the free ones.
void number(FieldNumbering& f, const std::vector<int>& group) {
  const std::size_t n = f.condition.size();
  f.free_index.assign(n, -1);
  std::vector<int> group_index;
  Triplets p;
  for (std::size_t i = 0; i < n; ++i) {
    if (f.condition[i] != -1) continue;  // prescribed, or unused (kUnused)
    int index;
    if (!group.empty() && group[i] >= 0) {
      if (group[i] >= static_cast<int>(group_index.size())) group_index.resize(group[i] + 1, -1);
      if (group_index[group[i]] < 0) group_index[group[i]] = f.n_free++;
      index = group_index[group[i]];
    } else {
      index = f.n_free++;
    }
    f.free_index[i] = index;
    p.emplace_back(static_cast<int>(i), index, 1.0);
  }
  f.prolongation.resize(static_cast<int>(n), f.n_free);
  f.prolongation.setFromTriplets(p.begin(), p.end());
}

/// The scalar field's conditions of `type` prescribe its vertices, and so
/// do the interfaces that are given it (`given`; their values are set before
/// each step, continuum_process.cpp).
FieldNumbering vertex_field(const ContinuumMesh& mesh, const std::vector<ContinuumCondition>& cs,
                            Type type, bool ContinuumCondition::Gives::*given) {
  FieldNumbering f;
  f.condition.assign(mesh.n_vertices, -1);
  f.value.assign(mesh.n_vertices, 0);
  for (std::size_t k = 0; k < cs.size(); ++k) {
    if (cs[k].type != type && !(cs[k].type == Type::Interface && cs[k].gives.*given)) continue;
    for (const BoundaryEdge& e : *mesh.boundary(cs[k].boundary))
      for (int v : {e.a, e.b}) {
        f.condition[v] = static_cast<int>(k);
        f.value[v] = cs[k].value + cs[k].gradient.dot(mesh.nodes[v]);
      }
  }
  number(f, {});
  return f;
}

/// The integration weight at x: 1 (per metre), or 2 pi r (axisymmetric).
double ring(const Vec2& x, bool axisymmetric) {
  return axisymmetric ? 2 * std::numbers::pi * x.x() : 1.0;
}

/// Edge loads: `per_edge(edge, condition, factor)` adds an edge's share.
template <class PerEdge>
void for_each_edge(const ContinuumMesh& mesh, const std::vector<ContinuumCondition>& cs, double t,
                   bool (*selects)(const ContinuumCondition&), PerEdge per_edge) {
  for (const ContinuumCondition& c : cs) {
    if (!selects(c)) continue;
    const double factor = c.factor(t);
    for (const BoundaryEdge& e : *mesh.boundary(c.boundary)) per_edge(e, c, factor);
  }
}

/// The rigid motions (translations along x and y, rotation about the
/// mesh's centre) that the displacement constraints leave free.
void check_rigid_motions(const ContinuumMesh& mesh, const FieldNumbering& u,
                         const std::vector<int>& group, bool axisymmetric) {
  Vec2 lo = mesh.nodes[0], hi = mesh.nodes[0];
  for (const Vec2& x : mesh.nodes) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  const Vec2 centre = (lo + hi) / 2;
  const double size = std::max((hi - lo).maxCoeff(), 1e-300);
  auto mode = [&](int entry) {
    const Vec2 x = (mesh.nodes[entry / 2] - centre) / size;
    return entry % 2 == 0 ? Eigen::Vector3d(1, 0, -x.y()) : Eigen::Vector3d(0, 1, x.x());
  };
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  std::vector<int> first_of_group;
  for (std::size_t i = 0; i < u.condition.size(); ++i) {
    const int entry = static_cast<int>(i);
    if (u.condition[i] >= 0) {
      const Eigen::Vector3d r = mode(entry);
      normal += r * r.transpose();
    } else if (group[i] >= 0) {
      if (group[i] >= static_cast<int>(first_of_group.size()))
        first_of_group.resize(group[i] + 1, -1);
      if (first_of_group[group[i]] < 0) {
        first_of_group[group[i]] = entry;
      } else {  // tied to the first: a motion must move both alike
        const Eigen::Vector3d r = mode(entry) - mode(first_of_group[group[i]]);
        normal += r * r.transpose();
      }
    }
  }
  // A ring can only move along its axis: the hoop strain holds the rest.
  if (axisymmetric)
    normal += Eigen::Vector3d(1, 0, 0) * Eigen::Vector3d(1, 0, 0).transpose() +
              Eigen::Vector3d(0, 0, 1) * Eigen::Vector3d(0, 0, 1).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(normal);
  if (eig.eigenvalues()(0) > 1e-10 * std::max(1.0, eig.eigenvalues()(2))) return;
  const Eigen::Vector3d free = eig.eigenvectors().col(0);
  const char* what = std::abs(free(2)) > 0.5                 ? "a rotation"
                     : std::abs(free(0)) > std::abs(free(1)) ? "a translation along x"
                                                             : "a translation along y";
  throw Error(std::string("found displacement conditions that leave the domain free to move "
                          "rigidly (") +
              what +
              "); expected displacement or plate conditions that hold both translations and the "
              "rotation, e.g. rollers on a vertical and on a horizontal side");
}

}  // namespace

Eigen::VectorXd FieldNumbering::free_part(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n_free);
  if (x.size() != static_cast<Eigen::Index>(free_index.size())) return y;
  for (std::size_t e = 0; e < free_index.size(); ++e)
    if (free_index[e] >= 0) y(free_index[e]) = x(static_cast<Eigen::Index>(e));
  return y;
}

FieldNumbering free_numbering(int n) {
  FieldNumbering f;
  f.condition.assign(n, -1);
  f.value.assign(n, 0);
  number(f, {});
  return f;
}

Eigen::VectorXd FieldNumbering::prescribed(const std::vector<ContinuumCondition>& conditions,
                                           double t) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<int>(condition.size()));
  for (std::size_t i = 0; i < condition.size(); ++i)
    if (condition[i] >= 0) x(i) = value[i] * conditions[condition[i]].factor(t);
  return x;
}

Eigen::VectorXd FieldNumbering::expand(const Eigen::VectorXd& y,
                                       const Eigen::VectorXd& prescribed) const {
  return prolongation * y + prescribed;
}

Eigen::VectorXd ContinuumConstraints::traction(const std::vector<ContinuumCondition>& cs,
                                               double t) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * mesh->n_nodes());
  for_each_edge(
      *mesh, cs, t,
      [](const ContinuumCondition& c) {
        return c.type == Type::Traction || c.type == Type::NormalPressure;
      },
      [&](const BoundaryEdge& e, const ContinuumCondition& c, double factor) {
        const Vec2 d = mesh->nodes[e.b] - mesh->nodes[e.a];
        const Vec2 outward(d.y(), -d.x());  // |outward| = edge length
        const Vec2 load =
            c.type == Type::Traction ? Vec2(c.vector * d.norm()) : Vec2(-c.value * outward);
        // Simpson (exact for N_a times the linear ring weight W): int N W
        // over a quadratic edge is L/6 W(a), L/6 W(b), 2L/3 W(mid).
        if (linear_displacement) {  // int N_a W over a linear edge: L/6 (W(a) + 2 W(mid))
          const double mid = 2 * ring(mesh->nodes[e.mid], axisymmetric);
          for (int node : {e.a, e.b})
            for (int comp = 0; comp < 2; ++comp)
              f(2 * node + comp) +=
                  (ring(mesh->nodes[node], axisymmetric) + mid) / 6 * factor * load(comp);
          return;
        }
        for (const auto& [node, w] : {std::pair{e.a, 1. / 6}, {e.b, 1. / 6}, {e.mid, 2. / 3}})
          for (int comp = 0; comp < 2; ++comp)
            f(2 * node + comp) += w * ring(mesh->nodes[node], axisymmetric) * factor * load(comp);
      });
  return f;
}

namespace {
/// int N_a W over a P1 edge, for its two vertices: L/6 (W(a) + 2 W(mid))
/// (Simpson, exact; half the length to each vertex in plane strain).
std::pair<double, double> edge_vertex_weights(const ContinuumMesh& mesh, const BoundaryEdge& e,
                                              bool axisymmetric) {
  const double sixth = (mesh.nodes[e.b] - mesh.nodes[e.a]).norm() / 6;
  const double mid = 2 * ring(mesh.nodes[e.mid], axisymmetric);
  return {sixth * (ring(mesh.nodes[e.a], axisymmetric) + mid),
          sixth * (ring(mesh.nodes[e.b], axisymmetric) + mid)};
}

/// An inflow per unit area on P1 edges (edge_vertex_weights). Heat
/// transfer's inflow is the h T_inf of h (T_inf - T).
Eigen::VectorXd vertex_inflow(const ContinuumMesh& mesh, const std::vector<ContinuumCondition>& cs,
                              double t, bool (*selects)(const ContinuumCondition&),
                              bool axisymmetric) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(mesh.n_vertices);
  for_each_edge(
      mesh, cs, t, selects, [&](const BoundaryEdge& e, const ContinuumCondition& c, double factor) {
        const double value = c.type == Type::HeatTransfer ? c.coefficient * c.value : c.value;
        const auto [wa, wb] = edge_vertex_weights(mesh, e, axisymmetric);
        f(e.a) += value * factor * wa;
        f(e.b) += value * factor * wb;
      });
  return f;
}

/// int_edge h N_a N_b W over the P1 edges of the heat transfer conditions.
/// N_a N_b W is cubic along an edge, so Simpson's rule is exact:
/// L/6 (W(a) + W(mid)) on the diagonal, L/6 W(mid) off it (W = 1 in plane
/// strain: L/3 and L/6).
Eigen::SparseMatrix<double> heat_transfer_matrix(const ContinuumMesh& mesh,
                                                 const std::vector<ContinuumCondition>& cs,
                                                 bool axisymmetric) {
  Triplets t;
  for_each_edge(
      mesh, cs, 0, [](const ContinuumCondition& c) { return c.type == Type::HeatTransfer; },
      [&](const BoundaryEdge& e, const ContinuumCondition& c, double /*factor*/) {
        const double l = (mesh.nodes[e.b] - mesh.nodes[e.a]).norm();
        const double mid = ring(mesh.nodes[e.mid], axisymmetric);
        t.emplace_back(e.a, e.a,
                       c.coefficient * l / 6 * (ring(mesh.nodes[e.a], axisymmetric) + mid));
        t.emplace_back(e.b, e.b,
                       c.coefficient * l / 6 * (ring(mesh.nodes[e.b], axisymmetric) + mid));
        t.emplace_back(e.a, e.b, c.coefficient * l / 6 * mid);
        t.emplace_back(e.b, e.a, c.coefficient * l / 6 * mid);
      });
  Eigen::SparseMatrix<double> m(mesh.n_vertices, mesh.n_vertices);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

}  // namespace

Eigen::VectorXd ContinuumConstraints::fluid_inflow(const std::vector<ContinuumCondition>& cs,
                                                   double t) const {
  return vertex_inflow(
      *mesh, cs, t, [](const ContinuumCondition& c) { return c.type == Type::FluidFlux; },
      axisymmetric);
}

Eigen::VectorXd ContinuumConstraints::heat_inflow(const std::vector<ContinuumCondition>& cs,
                                                  double t) const {
  return vertex_inflow(
      *mesh, cs, t,
      [](const ContinuumCondition& c) {
        return c.type == Type::HeatFlux || c.type == Type::HeatTransfer;
      },
      axisymmetric);
}

Eigen::VectorXd ContinuumConstraints::plate_forces(const std::vector<ContinuumCondition>& cs,
                                                   double t) const {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(displacement.n_free);
  for (const auto& [k, index] : plates) f(index) += cs[k].value * cs[k].factor(t);
  return f;
}

std::vector<int> ContinuumConstraints::interface_vertices(std::string_view boundary) const {
  std::vector<int> vertices;
  std::vector<char> seen(mesh->n_vertices, 0);
  for (const BoundaryEdge& e : *mesh->boundary(boundary))
    for (int v : {e.a, e.b})
      if (!seen[v]) {
        seen[v] = 1;
        vertices.push_back(v);
      }
  return vertices;
}

namespace {
/// The position of every vertex in `vertices` (-1: none).
std::vector<int> positions(int n_vertices, const std::vector<int>& vertices) {
  std::vector<int> at(n_vertices, -1);
  for (std::size_t i = 0; i < vertices.size(); ++i) at[vertices[i]] = static_cast<int>(i);
  return at;
}
}  // namespace

void ContinuumConstraints::add_interface_traction(std::string_view boundary,
                                                  const std::vector<int>& vertices,
                                                  const std::vector<Vec2>& traction,
                                                  Eigen::VectorXd& f) const {
  const std::vector<int> at = positions(mesh->n_vertices, vertices);
  const std::vector<BoundaryEdge>& edges = *mesh->boundary(boundary);
  std::vector<TractionPiece> whole;
  whole.reserve(edges.size());
  for (std::size_t k = 0; k < edges.size(); ++k)
    whole.push_back(
        {static_cast<int>(k), 0, 1, traction[at[edges[k].a]], traction[at[edges[k].b]]});
  add_interface_piece_traction(edges, whole, f);
}

void ContinuumConstraints::add_interface_piece_traction(const std::vector<BoundaryEdge>& edges,
                                                        const std::vector<TractionPiece>& pieces,
                                                        Eigen::VectorXd& f) const {
  // int N_a t W ds on each piece, s in [s0, s1] of its edge: the integrand
  // is of degree 4 at most (quadratic N, linear traction, linear ring
  // weight), which the 3-point Gauss rule integrates exactly.
  const double r = std::sqrt(0.6);
  const std::array<double, 3> g = {(1 - r) / 2, 0.5, (1 + r) / 2}, w = {5. / 18, 8. / 18, 5. / 18};
  for (const TractionPiece& p : pieces) {
    const BoundaryEdge& e = edges[p.edge];
    const Vec2 &xa = mesh->nodes[e.a], &xb = mesh->nodes[e.b];
    const double length = (xb - xa).norm() * (p.s1 - p.s0);
    for (int q = 0; q < 3; ++q) {
      const double s = p.s0 + g[q] * (p.s1 - p.s0);
      const Vec2 load = ((1 - g[q]) * p.t0 + g[q] * p.t1) *
                        (w[q] * length * ring((1 - s) * xa + s * xb, axisymmetric));
      const std::array<std::pair<int, double>, 3> shape =
          linear_displacement
              ? std::array<std::pair<int, double>, 3>{{{e.a, 1 - s}, {e.b, s}, {e.mid, 0}}}
              : std::array<std::pair<int, double>, 3>{{{e.a, (1 - s) * (1 - 2 * s)},
                                                       {e.b, s * (2 * s - 1)},
                                                       {e.mid, 4 * s * (1 - s)}}};
      for (const auto& [node, n] : shape)
        for (int comp = 0; comp < 2; ++comp) f(2 * node + comp) += n * load(comp);
    }
  }
}

void ContinuumConstraints::add_interface_piece_flux(const std::vector<BoundaryEdge>& edges,
                                                    const std::vector<HeatFluxPiece>& pieces,
                                                    Eigen::VectorXd& f) const {
  // Linear N times linear q: the 2-point Gauss rule is exact.
  const double g = 0.5 / std::sqrt(3.0);
  for (const HeatFluxPiece& p : pieces) {
    const BoundaryEdge& e = edges[p.edge];
    const double length = (mesh->nodes[e.b] - mesh->nodes[e.a]).norm() * (p.s1 - p.s0);
    for (const double u : {0.5 - g, 0.5 + g}) {
      const double s = p.s0 + u * (p.s1 - p.s0), q = (1 - u) * p.t0 + u * p.t1;
      f(e.a) += 0.5 * length * (1 - s) * q;
      f(e.b) += 0.5 * length * s * q;
    }
  }
}

std::vector<double> ContinuumConstraints::vertex_measure(std::string_view boundary,
                                                         const std::vector<int>& vertices) const {
  const std::vector<int> at = positions(mesh->n_vertices, vertices);
  std::vector<double> m(vertices.size(), 0);
  for (const BoundaryEdge& e : *mesh->boundary(boundary)) {
    const auto [wa, wb] = edge_vertex_weights(*mesh, e, axisymmetric);
    m[at[e.a]] += wa;
    m[at[e.b]] += wb;
  }
  return m;
}

ContinuumConstraints build_constraints(const ContinuumMesh& mesh,
                                       const std::vector<ContinuumCondition>& conditions,
                                       bool axisymmetric, bool linear_displacement) {
  ContinuumConstraints out;
  out.mesh = &mesh;
  out.axisymmetric = axisymmetric;
  out.linear_displacement = linear_displacement;
  FieldNumbering& u = out.displacement;
  const int nu = 2 * mesh.n_nodes();
  u.condition.assign(nu, -1);
  u.value.assign(nu, 0);
  std::vector<int> group(nu, -1);
  std::vector<int> plate_conditions;
  // Fixed components first; a plate ties the components no condition fixes.
  for (std::size_t k = 0; k < conditions.size(); ++k) {
    const ContinuumCondition& c = conditions[k];
    if (c.type != Type::Displacement) continue;
    for (const BoundaryEdge& e : *mesh.boundary(c.boundary))
      for (int node : {e.a, e.b, e.mid})
        for (int comp = 0; comp < 2; ++comp)
          if (c.fix[comp]) {
            u.condition[2 * node + comp] = static_cast<int>(k);
            u.value[2 * node + comp] = c.vector(comp);
          }
  }
  for (std::size_t k = 0; k < conditions.size(); ++k) {
    const ContinuumCondition& c = conditions[k];
    if (c.type != Type::RigidPlate) continue;
    const int id = static_cast<int>(plate_conditions.size());
    plate_conditions.push_back(static_cast<int>(k));
    for (const BoundaryEdge& e : *mesh.boundary(c.boundary))
      for (int node : {e.a, e.b, e.mid}) group[2 * node + c.axis] = id;
  }
  check_rigid_motions(mesh, u, group, axisymmetric);
  // P1 displacement: the midpoints carry no unknowns.
  if (linear_displacement)
    for (int node = mesh.n_vertices; node < mesh.n_nodes(); ++node)
      for (int comp = 0; comp < 2; ++comp) u.condition[2 * node + comp] = kUnused;
  number(u, group);
  for (std::size_t id = 0; id < plate_conditions.size(); ++id)
    for (int i = 0; i < nu; ++i)
      if (group[i] == static_cast<int>(id) && u.free_index[i] >= 0) {
        out.plates.emplace_back(plate_conditions[id], u.free_index[i]);
        break;
      }
  out.pressure =
      vertex_field(mesh, conditions, Type::FluidPressure, &ContinuumCondition::Gives::pressure);
  out.temperature =
      vertex_field(mesh, conditions, Type::Temperature, &ContinuumCondition::Gives::temperature);
  out.heat_transfer = heat_transfer_matrix(mesh, conditions, axisymmetric);
  return out;
}

}  // namespace fissure::continuum

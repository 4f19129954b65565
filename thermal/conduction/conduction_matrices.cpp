#include "thermal/conduction/conduction_matrices.h"

#include <Eigen/Dense>

namespace fissure::thermal {

Eigen::Matrix2d edge_mass(double length, bool lumped) {
  if (lumped) return Eigen::Matrix2d::Identity() * (length / 2);
  Eigen::Matrix2d w;
  w << 2, 1, 1, 2;
  return w * (length / 6);
}

ConductionMatrices conduction_matrices(const ThermalMesh& mesh, const ElementProperties& props,
                                       const std::vector<int>& node_dof, int n_dofs, bool lumped,
                                       const std::vector<EdgeTransfer>& joints,
                                       const std::vector<EdgeTransfer>& convective) {
  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> k, m;
  k.reserve(9 * mesh.triangles.size());
  m.reserve((lumped ? 3 : 9) * mesh.triangles.size());
  ConductionMatrices out;
  out.node_capacity.assign(mesh.nodes.size(), 0.0);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec2 &p0 = mesh.nodes[tri[0]], &p1 = mesh.nodes[tri[1]], &p2 = mesh.nodes[tri[2]];
    const double area = mesh.triangle_area[t], twice_area = 2 * area;
    // grad N_i = perp(opposite edge) / 2A.
    Eigen::Matrix<double, 2, 3> g;
    g << p1.y() - p2.y(), p2.y() - p0.y(), p0.y() - p1.y(),  //
        p2.x() - p1.x(), p0.x() - p2.x(), p1.x() - p0.x();
    g /= twice_area;
    const Eigen::Vector3d& c = props.conductivity[t];
    Eigen::Matrix2d lambda;
    lambda << c[0], c[2], c[2], c[1];
    const Eigen::Matrix3d ke = area * g.transpose() * lambda * g;
    const double rc = props.capacity[t] * area;
    for (int r = 0; r < 3; ++r) {
      const int dr = node_dof[tri[r]];
      out.node_capacity[tri[r]] += rc / 3;
      if (lumped) m.emplace_back(dr, dr, rc / 3);
      for (int s = 0; s < 3; ++s) {
        const int ds = node_dof[tri[s]];
        k.emplace_back(dr, ds, ke(r, s));
        if (!lumped) m.emplace_back(dr, ds, rc / 12 * (r == s ? 2 : 1));
      }
    }
  }
  // h int (T - T') (N - N') ds over a joint face: its edge a -> b faces the
  // partner's b' -> a' (the same points).
  for (const EdgeTransfer& j : joints) {
    const BoundaryEdge& e = mesh.boundary_edges[j.edge];
    const BoundaryEdge& f = mesh.boundary_edges[e.partner];
    const Eigen::Matrix2d w = j.h * edge_mass((mesh.nodes[e.b] - mesh.nodes[e.a]).norm(), lumped);
    const int mine[2] = {node_dof[e.a], node_dof[e.b]};
    const int theirs[2] = {node_dof[f.b], node_dof[f.a]};
    for (int r = 0; r < 2; ++r)
      for (int s = 0; s < 2; ++s) {
        k.emplace_back(mine[r], mine[s], w(r, s));
        k.emplace_back(mine[r], theirs[s], -w(r, s));
      }
  }
  for (const EdgeTransfer& c : convective) {
    const BoundaryEdge& e = mesh.boundary_edges[c.edge];
    const Eigen::Matrix2d w = c.h * edge_mass((mesh.nodes[e.b] - mesh.nodes[e.a]).norm(), lumped);
    const int dofs[2] = {node_dof[e.a], node_dof[e.b]};
    for (int r = 0; r < 2; ++r)
      for (int s = 0; s < 2; ++s) k.emplace_back(dofs[r], dofs[s], w(r, s));
  }
  out.conductance.resize(n_dofs, n_dofs);
  out.conductance.setFromTriplets(k.begin(), k.end());
  out.capacity.resize(n_dofs, n_dofs);
  out.capacity.setFromTriplets(m.begin(), m.end());
  return out;
}

}  // namespace fissure::thermal

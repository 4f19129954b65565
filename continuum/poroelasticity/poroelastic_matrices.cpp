#include "continuum/poroelasticity/poroelastic_matrices.h"

#include <algorithm>
#include <numeric>
#include <utility>

#include "core/geometry/hilbert_key.h"

#include "continuum/poroelasticity/taylor_hood.h"

namespace fissure::continuum {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

/// K_dr = lambda + G: the drained modulus of plane strain (d = 2,
/// lambda + 2G/d; theory.md 5.3).
double drained_modulus(const PoroMaterial& m) {
  return m.lame_lambda() + m.shear_modulus();
}

/// `into` := the rows x cols matrix of `t`, whose memory is let go at once
/// (the triplets of K take twice the matrix). Written in place: Eigen 3.4's
/// SparseMatrix has no move assignment, and a returned matrix is copied.
void fill(SparseMatrix& into, Triplets&& t, int rows, int cols) {
  into.resize(rows, cols);
  into.setFromTriplets(t.begin(), t.end());
  Triplets().swap(t);
}

}  // namespace

Vector4 initial_stress4(const Eigen::Vector3d& s) {
  return Vector4(s(0), s(1), s(2), s(0));
}

std::vector<char> owned_triangles(const ContinuumMesh& mesh, int rank, int ranks) {
  const int nt = mesh.n_triangles();
  if (ranks <= 1) return std::vector<char>(nt, 1);
  Eigen::AlignedBox2d box;
  for (int v = 0; v < mesh.n_vertices; ++v) box.extend(mesh.nodes[v]);
  std::vector<Vec2> centroids(nt);
  for (int e = 0; e < nt; ++e) {
    const std::array<int, 6>& t = mesh.triangles[e];
    centroids[e] = (mesh.nodes[t[0]] + mesh.nodes[t[1]] + mesh.nodes[t[2]]) / 3;
  }
  const std::vector<int> order = hilbert_order(centroids, box.min(), box.max());
  std::vector<char> owned(nt, 0);
  const long long first = static_cast<long long>(nt) * rank / ranks,
                  last = static_cast<long long>(nt) * (rank + 1) / ranks;
  for (long long k = first; k < last; ++k) owned[order[k]] = 1;
  return owned;
}

void assemble_poroelastic(const ContinuumMesh& mesh, const ContinuumControls& c,
                          const Vec2& gravity, const std::vector<char>& owned,
                          PoroelasticMatrices& out) {
  const int nu = 2 * mesh.n_nodes(), np = mesh.n_vertices;
  // A scene without heat gets its thermal matrices, and one without the
  // undrained split its K_v, empty (no entries, their sizes): K_v alone is
  // as large as K (a fifth of the peak memory at 256 x 256 cells).
  const bool heat = c.with_temperature(),
             undrained_split = c.scheme == ContinuumControls::Scheme::Undrained;
  Triplets k, kv, q, kt, s, fs, w, ct, lt;
  const std::size_t nt = mesh.triangles.size();
  k.reserve(144 * nt);
  if (undrained_split) kv.reserve(144 * nt);
  q.reserve(36 * nt);
  if (heat) kt.reserve(36 * nt);
  for (Triplets* t : {&s, &fs}) t->reserve(9 * nt);
  if (heat)
    for (Triplets* t : {&w, &ct, &lt}) t->reserve(9 * nt);
  out.body_force = Eigen::VectorXd::Zero(nu);
  out.initial_stress = Eigen::VectorXd::Zero(nu);
  out.elasticity.resize(nt);
  out.permeability.resize(nt);
  out.biot.resize(nt);
  out.thermal_stress_modulus.resize(nt);
  const bool geostatic = !c.initial_stress.isZero() || !c.initial_stress_gradient.isZero();

  for (std::size_t e = 0; e < nt; ++e) {
    const std::array<int, 6>& tri = mesh.triangles[e];
    const PoroMaterial& m = c.materials[mesh.triangle_material[e]];
    const Matrix4 d = elasticity_matrix(m.young_modulus, m.poisson_ratio);
    const double alpha = m.biot_coefficient, gamma = 3 * m.bulk_modulus() * m.thermal_expansion;
    out.elasticity[e] = d;
    out.biot[e] = alpha;
    out.thermal_stress_modulus[e] = gamma;
    out.permeability[e] = m.permeability;
    if (!owned.empty() && !owned[e]) continue;  // another rank's share
    const TriangleGeometry g({mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]},
                             c.axisymmetric, c.linear_displacement);
    const ElementMatrices em = element_matrices(g, d);
    const double beta_fs = c.fixed_stress_factor * alpha * alpha / drained_modulus(m);
    // Rodrigo et al. (2016): tau = factor alpha^2 h^2 / (4 (lambda + 2G)) on
    // grad p_t, h the triangle's longest edge.
    double h2 = 0;
    for (int k = 0; k < 3; ++k) h2 = std::max(h2, (g.x[(k + 1) % 3] - g.x[k]).squaredNorm());
    const double stabilization = c.pressure_stabilization * alpha * alpha * h2 /
                                 (4 * (m.lame_lambda() + 2 * m.shear_modulus()));

    int u[12];
    for (int a = 0; a < 6; ++a) u[2 * a] = 2 * tri[a], u[2 * a + 1] = 2 * tri[a] + 1;
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        k.emplace_back(u[i], u[j], em.stiffness(i, j));
        if (undrained_split)
          kv.emplace_back(u[i], u[j], alpha * alpha * m.biot_modulus * em.volumetric(i, j));
      }
      for (int j = 0; j < 3; ++j) {
        q.emplace_back(u[i], tri[j], alpha * em.coupling(i, j));
        if (heat) kt.emplace_back(u[i], tri[j], gamma * em.coupling(i, j));
      }
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        s.emplace_back(tri[i], tri[j],
                       em.mass(i, j) / m.biot_modulus + stabilization * em.laplacian(i, j));
        fs.emplace_back(tri[i], tri[j], beta_fs * em.mass(i, j));
        if (!heat) continue;
        w.emplace_back(tri[i], tri[j], m.fluid_thermal_expansion * em.mass(i, j));
        ct.emplace_back(tri[i], tri[j], m.heat_capacity * em.mass(i, j));
        lt.emplace_back(tri[i], tri[j], m.conductivity * em.laplacian(i, j));
      }

    for (int a = 0; a < 6; ++a)
      for (int comp = 0; comp < 2; ++comp)
        out.body_force(2 * tri[a] + comp) += m.density * gravity(comp) * em.shape_integral(a);
    if (geostatic) {
      const Vector12 f = stress_vector(g, initial_stress4(c.initial_stress),
                                       initial_stress4(c.initial_stress_gradient), c.reference_y);
      for (int i = 0; i < 12; ++i) out.initial_stress(u[i]) += f(i);
    }
  }
  fill(out.stiffness, std::move(k), nu, nu);
  fill(out.undrained, std::move(kv), nu, nu);
  fill(out.coupling, std::move(q), nu, np);
  fill(out.thermal_stress, std::move(kt), nu, np);
  fill(out.storage, std::move(s), np, np);
  fill(out.fixed_stress, std::move(fs), np, np);
  fill(out.pressurization, std::move(w), np, np);
  fill(out.heat_capacity, std::move(ct), np, np);
  fill(out.conduction, std::move(lt), np, np);
  assemble_flow_terms(mesh, c, gravity, owned, out);
}

void assemble_flow_terms(const ContinuumMesh& mesh, const ContinuumControls& c, const Vec2& gravity,
                         const std::vector<char>& owned, PoroelasticMatrices& m) {
  const int np = mesh.n_vertices;
  Triplets h;
  h.reserve(9 * mesh.triangles.size());
  m.gravity_flow = Eigen::VectorXd::Zero(np);
  for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
    if (!owned.empty() && !owned[e]) continue;  // another rank's share
    const std::array<int, 6>& tri = mesh.triangles[e];
    const TriangleGeometry g({mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]},
                             c.axisymmetric, c.linear_displacement);
    const double measure = triangle_measure(g);
    const Eigen::Matrix<double, 2, 3> dn = p1_gradients(g);
    const Eigen::Vector3d& k = m.permeability[e];
    Eigen::Matrix2d kk;
    kk << k(0), k(2), k(2), k(1);
    // int grad N^T (k / mu) grad N, and int grad N^T (k / mu) rho_f g: the
    // flux that balances hydrostatic pressure.
    const Eigen::Matrix3d em = measure * dn.transpose() * kk * dn;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) h.emplace_back(tri[i], tri[j], em(i, j) / c.viscosity);
    const Eigen::Vector3d gf =
        measure * dn.transpose() * kk * gravity * (c.fluid_density / c.viscosity);
    for (int i = 0; i < 3; ++i) m.gravity_flow(tri[i]) += gf(i);
  }
  fill(m.mobility, std::move(h), np, np);
}

double largest_coupling_strength(const ContinuumMesh& mesh, const ContinuumControls& c) {
  double tau = 0;
  for (int material : mesh.triangle_material) {
    const PoroMaterial& m = c.materials[material];
    tau = std::max(tau,
                   m.biot_coefficient * m.biot_coefficient * m.biot_modulus / drained_modulus(m));
  }
  return tau;
}

}  // namespace fissure::continuum

// Deformable DEM blocks (mechanics/dem/zone_mesh.h, zoned_block.h), the
// pieces against exact answers:
//  * meshing: the zones tile the polygon (areas to round-off, all
//    counter-clockwise), whatever its orientation, convexity or holes; the
//    boundary is a loop of nodes through every vertex, no piece longer than
//    the zone size; bad input refused;
//  * the patch test: a uniform velocity gradient gives every zone the same
//    stress, the closed form of plane-strain Hooke to round-off, and no
//    force on the interior nodes (for both volumetric formulations);
//  * objectivity: a block under stress turned rigidly by a quarter turn in
//    1,000 steps carries its stress in the material's axes (sigma_xx
//    becomes sigma_yy to round-off), with no strain energy gained;
//  * the critical time step: the zones' element bound is below the true
//    limit 2 / omega_max of the assembled block (power iteration on its
//    forces), and not far below it; a step just above the true limit grows
//    without bound, one at the bound does not;
//  * free fall: every node falls exactly g t^2 / 2 from the half-step
//    start, unstrained;
//  * lumped masses sum to rho times the area.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>
#include <utility>
#include <vector>

#include "core/base/errors.h"
#include "mechanics/dem/zoned_block.h"

namespace fissure::dem {
namespace {

double zone_area(const std::vector<Vec2>& x, const std::array<int, 3>& t) {
  return 0.5 * orient(x[t[0]], x[t[1]], x[t[2]]);
}

/// An L-shaped (concave) block, given clockwise.
Polygon l_block() {
  return Polygon({{0, 0}, {0, 2}, {1, 2}, {1, 1}, {3, 1}, {3, 0}});
}

void expect_tiles(const Polygon& polygon, double zone_size) {
  const ZoneMesh m = mesh_block(polygon, zone_size);
  double area = 0, polygon_area = std::abs(signed_area(polygon.loop(0)));
  for (int l = 1; l < polygon.n_loops(); ++l)
    polygon_area -= std::abs(signed_area(polygon.loop(l)));
  std::map<std::pair<int, int>, int> edges;  // directed zone edges
  for (const auto& t : m.zones) {
    const double a = zone_area(m.nodes, t);
    EXPECT_GT(a, 0);
    area += a;
    for (int k = 0; k < 3; ++k) {
      ++edges[{t[k], t[(k + 1) % 3]}];
      // Inside, the mesher does not split a zone whose refinement point
      // would fall on the boundary: a little longer edges there.
      EXPECT_LE((m.nodes[t[k]] - m.nodes[t[(k + 1) % 3]]).norm(), 1.25 * zone_size);
    }
  }
  EXPECT_NEAR(area, polygon_area, 1e-12 * polygon_area);
  ASSERT_EQ(static_cast<int>(m.boundary.size()), polygon.n_loops());
  for (std::size_t l = 0; l < m.boundary.size(); ++l) {
    std::vector<Vec2> loop;
    for (int a : m.boundary[l]) loop.push_back(m.nodes[a]);
    const double expected = std::abs(signed_area(polygon.loop(static_cast<int>(l))));
    // Outer loop counter-clockwise, holes clockwise: the block on the left.
    EXPECT_NEAR(signed_area(loop), l == 0 ? expected : -expected, 1e-12 * expected);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int a = m.boundary[l][k], b = m.boundary[l][(k + 1) % loop.size()];
      EXPECT_LE((loop[k] - loop[(k + 1) % loop.size()]).norm(), zone_size * (1 + 1e-9));
      // A boundary edge is an edge of one zone, in the loop's direction.
      EXPECT_EQ(edges[std::pair(a, b)], 1) << "boundary edge " << a << "-" << b;
      EXPECT_EQ(edges.count(std::pair(b, a)), 0u);
    }
  }
  ASSERT_EQ(static_cast<int>(m.corner_nodes.size()), polygon.n_vertices());
  for (int v = 0; v < polygon.n_vertices(); ++v)
    EXPECT_EQ(m.nodes[m.corner_nodes[v]], polygon.vertices[v]);
}

TEST(DemZonedBlock, ZonesTileConvexConcaveAndHoledPolygons) {
  expect_tiles(Polygon({{0, 0}, {2, 0}, {2, 1}, {0, 1}}), 0.25);
  expect_tiles(l_block(), 0.2);
  Polygon holed({{0, 0}, {4, 0}, {4, 3}, {0, 3}});
  holed.add_loop(std::vector<Vec2>{{1, 1}, {1, 2}, {2.5, 2}, {2.5, 1}});
  expect_tiles(holed, 0.3);
  // A block smaller than a zone: its own corners only.
  const ZoneMesh one = mesh_block(Polygon({{0, 0}, {1, 0}, {0, 1}}), 5);
  EXPECT_EQ(one.zones.size(), 1u);
  EXPECT_EQ(one.nodes.size(), 3u);
}

TEST(DemZonedBlock, BadMeshInputIsRefused) {
  const Polygon square({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  EXPECT_THROW(mesh_block(square, 0), GeometryError);
  EXPECT_THROW(mesh_block(square, std::nan("")), GeometryError);
  EXPECT_THROW(mesh_block(Polygon({{0, 0}, {1, 0}, {2, 0}}), 0.5), GeometryError);
  EXPECT_THROW(mesh_block(Polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}}), 0.5), GeometryError);
  const ZoneMaterial bad{10e9, 0.5, 2500};
  EXPECT_THROW(ZonedBlock(mesh_block(square, 0.5), bad), Error);
  // A hand-made mesh: a node of no zone (no mass), a clockwise zone.
  const ZoneMaterial rock{10e9, 0.25, 2500};
  ZoneMesh loose{{{0, 0}, {1, 0}, {0, 1}, {5, 5}}, {{0, 1, 2}}, {{0, 1, 2}}, {0, 1, 2}};
  EXPECT_THROW(ZonedBlock(loose, rock), Error);
  ZoneMesh clockwise{{{0, 0}, {1, 0}, {0, 1}}, {{0, 2, 1}}, {{0, 1, 2}}, {0, 1, 2}};
  EXPECT_THROW(ZonedBlock(clockwise, rock), GeometryError);
}

constexpr ZoneMaterial kRock{10e9, 0.25, 2500};

/// The stress of a zone as a vector, for comparisons.
std::array<double, 4> as_array(const ZoneStress& s) {
  return {s.xx, s.yy, s.xy, s.zz};
}

TEST(DemZonedBlock, AUniformStrainGivesAUniformStressExactly) {
  // An irregular pentagon, meshed unstructured.
  const Polygon pentagon({{0, 0}, {2.1, 0.2}, {2.6, 1.7}, {1.0, 2.4}, {-0.3, 1.2}});
  Eigen::Matrix2d l;               // a velocity gradient without spin, 1/s (the spin's
  l << 2e-3, 1e-3, 1e-3, -0.5e-3;  // turn is the next test's)
  const double dt = 1e-4;
  for (VolumetricStrain formulation : {VolumetricStrain::NodalAverage, VolumetricStrain::PerZone}) {
    ZonedBlock block(mesh_block(pentagon, 0.3), kRock, formulation);
    ASSERT_GT(block.n_zones(), 50);
    std::set<int> on_boundary(block.boundary()[0].begin(), block.boundary()[0].end());
    for (int a = 0; a < block.n_nodes(); ++a) {
      block.set_velocity(a, l * block.positions()[a]);
      block.fix(a, true, true);  // held: the strain grows uniformly
    }
    // Step 1 moves the nodes (no strain from the initial velocities), step
    // 2 strains the zones by the gradient over the moved geometry,
    // L (I + L dt)^-1, and steps 3.. likewise.
    const int steps = 4;
    for (int k = 0; k < steps; ++k) block.step(dt, Vec2::Zero(), {});
    Eigen::Matrix2d strain = Eigen::Matrix2d::Zero(), deformation = Eigen::Matrix2d::Identity();
    for (int k = 0; k < steps; ++k) {
      if (k > 0) {
        // Gradient over the increment's midpoint geometry.
        const Eigen::Matrix2d g = l * (deformation - 0.5 * dt * l).inverse() * dt;
        strain += 0.5 * (g + g.transpose());
      }
      deformation += dt * l;
    }
    const double lambda = kRock.bulk() - 2 * kRock.shear() / 3, g2 = 2 * kRock.shear();
    const double tr = strain.trace();
    const std::array<double, 4> expected = {lambda * tr + g2 * strain(0, 0),
                                            lambda * tr + g2 * strain(1, 1), g2 * strain(0, 1),
                                            lambda * tr};
    const std::array<double, 4> first = as_array(block.stress(0));
    double scale = 0;
    for (double v : expected) scale = std::max(scale, std::abs(v));
    for (int z = 0; z < block.n_zones(); ++z) {
      const std::array<double, 4> s = as_array(block.stress(z));
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(s[i], first[i], 1e-12 * scale) << "zone " << z;
    }
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(first[i], expected[i], 1e-12 * scale) << i;
    // Interior nodes: the zones' forces cancel (the step's unbalanced force
    // is the boundary's only).
    ZonedBlock free_block(mesh_block(pentagon, 0.3), kRock, formulation);
    free_block.set_stress({1e6, -2e6, 0.5e6, 0.3e6});
    free_block.step(dt, Vec2::Zero(), {});
    double worst_inside = 0, worst_boundary = 0;
    for (int a = 0; a < free_block.n_nodes(); ++a) {
      double& worst = on_boundary.count(a) ? worst_boundary : worst_inside;
      worst = std::max(worst, free_block.velocities()[a].norm());
    }
    EXPECT_LT(worst_inside, 1e-12 * worst_boundary);
  }
}

TEST(DemZonedBlock, ARigidTurnCarriesTheStressInTheMaterialAxes) {
  ZonedBlock block(mesh_block(l_block(), 0.25), kRock);
  block.set_stress({1e6, 0, 0, 0.25e6});
  const double u0 = block.strain_energy();
  const Vec2 centre(1, 1);
  const int steps = 1000;
  const double dt = 1e-3, turn = 0.5 * std::numbers::pi / steps;
  const Eigen::Matrix2d r{{std::cos(turn), -std::sin(turn)}, {std::sin(turn), std::cos(turn)}};
  for (int a = 0; a < block.n_nodes(); ++a) block.fix(a, true, true);
  // Each step's strain comes from the velocities that brought the nodes
  // there, its move from the chord of each node's arc (the positions turn
  // exactly): the two halves of the step apart.
  for (int k = 0; k < steps; ++k) {
    block.update_zones(dt);
    for (int a = 0; a < block.n_nodes(); ++a) {
      const Vec2 x = block.positions()[a] - centre;
      block.set_velocity(a, (r * x - x) / dt);
    }
    block.move_nodes(dt, Vec2::Zero(), {});
  }
  block.update_zones(dt);
  for (int z = 0; z < block.n_zones(); ++z) {
    const ZoneStress s = block.stress(z);
    EXPECT_NEAR(s.xx, 0, 1e-9 * 1e6) << z;
    EXPECT_NEAR(s.yy, 1e6, 1e-9 * 1e6) << z;
    EXPECT_NEAR(s.xy, 0, 1e-9 * 1e6) << z;
    EXPECT_NEAR(s.zz, 0.25e6, 1e-9 * 1e6) << z;
  }
  EXPECT_NEAR(block.strain_energy(), u0, 1e-9 * u0);
  // The block's corner (1, 2) went to (0, 1) (turned about (1, 1)).
  EXPECT_NEAR((block.positions()[block.corner_nodes()[2]] - Vec2(0, 1)).norm(), 0, 1e-12);
}

/// The largest squared frequency of the block's free nodes, lambda_max(M^-1
/// K), by power iteration with the Rayleigh quotient in the mass inner
/// product (a lower bound that converges to it). K u is applied through the
/// block's own forces: a first step moves the nodes by u, a second one
/// strains the zones by it and accelerates the nodes by -M^-1 K u.
double largest_frequency_squared(const ZoneMesh& mesh, const ZoneMaterial& material,
                                 VolumetricStrain formulation) {
  const double dt = 1e-6, scale = 1e-9;  // displacements of a nanometre: linear
  const int n = static_cast<int>(mesh.nodes.size());
  std::vector<Vec2> u(n);
  for (int a = 0; a < n; ++a) u[a] = scale * Vec2(std::sin(1.3 * a + 0.2), std::cos(0.7 * a));
  double lambda = 0;
  for (int it = 0; it < 2000; ++it) {
    ZonedBlock block(mesh, material, formulation);
    for (int a = 0; a < n; ++a) {
      block.set_velocity(a, u[a] / dt);
      block.fix(a, true, true);
    }
    block.step(dt, Vec2::Zero(), {});
    for (int a = 0; a < n; ++a) block.fix(a, false, false);
    block.step(dt, Vec2::Zero(), {});
    std::vector<Vec2> w(n);  // M^-1 K u
    double uku = 0, umu = 0, largest = 0;
    for (int a = 0; a < n; ++a) {
      w[a] = -(block.velocities()[a] - u[a] / dt) / dt;
      uku += block.masses()[a] * w[a].dot(u[a]);
      umu += block.masses()[a] * u[a].squaredNorm();
      largest = std::max(largest, w[a].norm());
    }
    lambda = uku / umu;
    for (int a = 0; a < n; ++a) u[a] = scale * w[a] / largest;
  }
  return lambda;
}

/// The largest ratio of the energy to the first over `steps` undamped
/// steps of dt from a random displacement (kinetic + strain).
double energy_growth(const ZoneMesh& mesh, const ZoneMaterial& material, double dt, int steps) {
  ZonedBlock block(mesh, material);
  for (int a = 0; a < block.n_nodes(); ++a)
    block.set_velocity(a, 1e-6 * Vec2(std::sin(2.1 * a), std::cos(1.7 * a + 0.4)));
  double first = 0, largest = 0;
  for (int k = 0; k < steps; ++k) {
    block.step(dt, Vec2::Zero(), {});
    const EnergyBalance e = block.energy();
    if (k == 0) first = e.kinetic + e.strain;
    largest = std::max(largest, (e.kinetic + e.strain) / first);
  }
  return largest;
}

TEST(DemZonedBlock, TheCriticalStepIsBelowTheBlocksAndCloseToIt) {
  for (double nu : {0.25, 0.49}) {
    const ZoneMaterial rock{10e9, nu, 2500};
    const ZoneMesh mesh = mesh_block(l_block(), 0.5);
    for (VolumetricStrain f : {VolumetricStrain::NodalAverage, VolumetricStrain::PerZone}) {
      const ZonedBlock block(mesh, rock, f);
      const double bound = block.critical_time_step();
      const double exact = 2 / std::sqrt(largest_frequency_squared(mesh, rock, f));
      std::printf("nu %.2f %s: element bound %.4e s, block's limit %.4e s (ratio %.3f)\n", nu,
                  f == VolumetricStrain::NodalAverage ? "nodal average" : "per zone", bound, exact,
                  bound / exact);
      EXPECT_LE(bound, exact * (1 + 1e-6));
      EXPECT_GT(bound, 0.3 * exact);
      if (f == VolumetricStrain::NodalAverage) {
        // Central differences: bounded at the bound, growing beyond the
        // block's limit (the top mode amplified about 1.9 times a step).
        EXPECT_LT(energy_growth(mesh, rock, bound, 2000), 2.0);
        EXPECT_GT(energy_growth(mesh, rock, 1.05 * exact, 300), 1e6);
      }
    }
  }
  // The element bound against h / c_p for an equilateral zone of side 1 m
  // (altitude sqrt(3)/2): 2 / omega = 0.816 h / c_p at nu = 0.25.
  const ZonedBlock one(mesh_block(Polygon({{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}}), 2), kRock);
  EXPECT_NEAR(one.critical_time_step() * kRock.p_wave_speed() / (std::sqrt(3.0) / 2), 0.8165, 1e-4);
}

TEST(DemZonedBlock, AFreeBlockFallsExactlyFromTheHalfStepStart) {
  // Constant acceleration: central differences from v^{-1/2} = v^0 - g dt/2
  // give x^n = x^0 + v^0 t + g t^2 / 2 exactly (v^0 for v^{-1/2} would put
  // every node g dt t / 2 lower), and a rigid translation strains nothing.
  ZonedBlock block(mesh_block(l_block(), 0.3), kRock);
  const std::vector<Vec2> start = block.positions();
  const Vec2 g(0, -9.81), v0(0.5, 2);
  for (int a = 0; a < block.n_nodes(); ++a) block.set_velocity(a, v0);
  const double dt = 0.5 * block.critical_time_step();
  const int n = 2000;
  for (int k = 0; k < n; ++k) block.step(dt, g, {});
  const double t = n * dt;
  for (int a = 0; a < block.n_nodes(); ++a)
    EXPECT_NEAR((block.positions()[a] - start[a] - v0 * t - 0.5 * g * t * t).norm(), 0, 1e-13);
  for (int z = 0; z < block.n_zones(); ++z) {
    const ZoneStress s = block.stress(z);
    EXPECT_LT(std::abs(s.xx) + std::abs(s.yy) + std::abs(s.xy) + std::abs(s.zz), 1e-3) << z;
  }
  std::printf("fell %.4e m in %d steps\n", (block.positions()[0] - start[0]).norm(), n);
}

TEST(DemZonedBlock, MassesSumToTheBlocksMass) {
  const ZonedBlock block(mesh_block(l_block(), 0.2), kRock);
  double m = 0;
  for (double x : block.masses()) m += x;
  EXPECT_NEAR(m, kRock.density * 4.0, 1e-12 * m);
  EXPECT_NEAR(kRock.p_wave_speed(), std::sqrt((kRock.bulk() + 4 * kRock.shear() / 3) / 2500), 1e-9);
  EXPECT_NEAR(kRock.constrained(), 10e9 * 0.75 / (1.25 * 0.5), 1e-3);  // E (1-nu)/((1+nu)(1-2nu))
}

}  // namespace
}  // namespace fissure::dem

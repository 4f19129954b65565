// Deformable DEM blocks at rest (mechanics/dem/zoned_block.h), brought to
// equilibrium by the explicit steps with Cundall's local damping (0.8, at
// half the critical step) until the unbalanced-force ratio (largest
// unbalanced nodal force / mean applied) is below 1e-7 or 1e-6, against
// closed forms (docs/dem.md, "Deformable blocks"):
//  * a block under uniaxial load: 2 m x 4 m, unstructured zones of 0.25 m,
//    a roller base, 1 MPa on its top as nodal forces: uniform stress
//    sigma_yy = -p, sigma_xx = 0, sigma_zz = -nu p (plane strain), the top
//    settling by (1 - nu^2) p H / E, the side moving out by nu (1 + nu) p
//    W / E. Constant-strain zones hold a uniform state exactly: what is left
//    is the updated configuration's share, of the order of the strain
//    (3e-5 here), and the rest of the unbalanced force;
//  * Kirsch's plate with a circular hole (a = 1 m) under a far stress
//    sigma_0 along x: a quarter ring a <= r <= 4 a with the exact Kirsch
//    tractions on its outer side (so that the finite plate has the infinite
//    one's solution) and symmetry rollers, structured zones (6, 12 and 24
//    along the quarter hole, rings growing to keep them square). Measured:
//    the hoop stress concentration at the hole's top (3 sigma_0: the
//    stresses of the first two rings there, averaged over each
//    quadrilateral of two zones, extrapolated to the hole) and the hole's
//    top moving by -sigma_0 a (1 - nu) / (2 G); the observed orders printed
//    and asserted (1.5 and 1.9 observed: between first and second order
//    for the stress, second for the displacement);
//  * the plate nearly incompressible (nu = 0.49), meshed by the block
//    mesher (zones of a/8 at the hole to a/2 at the sides of a 3 a square):
//    with the nodal average its hoop stress on the hole and its
//    displacement are as good as at nu = 0.25; the plain constant-strain
//    triangle locks (hoop stress 7 times further off, the hole moving a
//    third less).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>
#include <vector>

#include "mechanics/dem/zoned_block.h"

namespace fissure::dem {
namespace {

using NodalLoads = std::vector<std::pair<int, Vec2>>;

/// Steps with local damping until the unbalanced-force ratio is below
/// `ratio`; returns the steps taken (max_steps + 1 when it was not reached).
int settle(ZonedBlock& block, const NodalLoads& loads, double ratio, int max_steps) {
  const double dt = 0.5 * block.critical_time_step();
  const DampingControls damping{0.8, 0};
  for (int k = 1; k <= max_steps; ++k) {
    for (const auto& [node, force] : loads) block.add_force(node, force);
    block.step(dt, Vec2::Zero(), damping);
    const UnbalancedForce& f = block.unbalanced_force();
    if (k > 10 && f.largest < ratio * f.mean_applied) return k;
  }
  return max_steps + 1;
}

/// The uniaxial block's errors are near the strain's order (1e-5): it is
/// brought closer to rest than the plates, whose discretization errors are
/// 1e-3 and above (1e-6 instead of 1e-5 changes their errors by 5 %).
constexpr double kRatio = 1e-7, kPlateRatio = 1e-6;

TEST(DemZonedStatics, ABlockUnderUniaxialLoadMatchesTheClosedForm) {
  const double w = 2, h = 4, p = 1e6;
  const ZoneMaterial rock{10e9, 0.25, 2500};
  ZonedBlock block(mesh_block(Polygon({{0, 0}, {w, 0}, {w, h}, {0, h}}), 0.25), rock);
  std::vector<Vec2> start = block.positions();
  NodalLoads loads;
  const std::vector<int>& loop = block.boundary()[0];
  for (std::size_t k = 0; k < loop.size(); ++k) {
    const int a = loop[k], b = loop[(k + 1) % loop.size()];
    const Vec2 &xa = start[a], &xb = start[b];
    if (xa.y() == h && xb.y() == h) {  // the top: p over the edge, half at each end
      const Vec2 f(0, -0.5 * p * std::abs(xb.x() - xa.x()));
      loads.emplace_back(a, f);
      loads.emplace_back(b, f);
    }
  }
  int corner = -1;
  for (int a = 0; a < block.n_nodes(); ++a) {
    if (start[a].y() != 0) continue;
    block.fix(a, start[a].x() == 0, true);  // rollers; the corner (0, 0) pinned
    if (start[a].x() == 0) corner = a;
  }
  ASSERT_GE(corner, 0);
  const int steps = settle(block, loads, kRatio, 20000);
  std::printf("uniaxial: %d zones at rest (ratio %.0e) after %d steps\n", block.n_zones(), kRatio,
              steps);
  ASSERT_LE(steps, 20000);

  const double nu = rock.poisson, e = rock.young;
  double worst_stress = 0, worst_top = 0, worst_side = 0;
  for (int z = 0; z < block.n_zones(); ++z) {
    const ZoneStress s = block.stress(z);
    for (double err : {s.xx, s.yy + p, s.xy, s.zz + nu * p})
      worst_stress = std::max(worst_stress, std::abs(err) / p);
  }
  const double top = -(1 - nu * nu) * p * h / e, side = nu * (1 + nu) * p * w / e;
  for (int a = 0; a < block.n_nodes(); ++a) {
    const Vec2 u = block.positions()[a] - start[a];
    // Linear in the coordinates: u_y = top y / h, u_x = side x / w.
    worst_top = std::max(worst_top, std::abs(u.y() - top * start[a].y() / h) / std::abs(top));
    worst_side = std::max(worst_side, std::abs(u.x() - side * start[a].x() / w) / side);
  }
  std::printf(
      "uniaxial: largest stress error %.2e p, displacement error %.2e (vertical), %.2e "
      "(lateral) of the closed form\n",
      worst_stress, worst_top, worst_side);
  EXPECT_LT(worst_stress, 1e-4);  // the strain's order (3e-5) and the residual
  EXPECT_LT(worst_top, 1e-3);
  EXPECT_LT(worst_side, 1e-3);
}

/// Kirsch's solution: a circular hole of radius a in an infinite plate
/// under sigma_0 along x (tension positive), plane strain.
struct Kirsch {
  double a = 1, sigma0 = 1e6;
  ZoneMaterial rock;

  ZoneStress stress(const Vec2& x) const {
    const double r = x.norm(), t = std::atan2(x.y(), x.x());
    const double q = a * a / (r * r), c2 = std::cos(2 * t), s2 = std::sin(2 * t);
    const double rr = 0.5 * sigma0 * (1 - q) + 0.5 * sigma0 * (1 - 4 * q + 3 * q * q) * c2;
    const double tt = 0.5 * sigma0 * (1 + q) - 0.5 * sigma0 * (1 + 3 * q * q) * c2;
    const double rt = -0.5 * sigma0 * (1 + 2 * q - 3 * q * q) * s2;
    const double c = std::cos(t), s = std::sin(t);
    return {rr * c * c + tt * s * s - 2 * rt * s * c, rr * s * s + tt * c * c + 2 * rt * s * c,
            (rr - tt) * s * c + rt * (c * c - s * s), rock.poisson * (rr + tt)};
  }
  /// The top of the hole, (0, a), moves by this along y.
  double hole_top_displacement() const {
    return -sigma0 * a * (1 - rock.poisson) / (2 * rock.shear());
  }
};

struct KirschResult {
  int zones = 0, steps = 0;
  double hoop_rms = 0;   ///< the hole's zones' hoop stress error, RMS, of 3 sigma_0
  double top_error = 0;  ///< the hole's top displacement, relative
};

/// Tractions t = sigma n of Kirsch's field on the boundary edges for which
/// `loaded` holds (n the edge's outward normal: the block is on the left),
/// integrated against the edge's linear shape functions (3-point Gauss: the
/// traction is smooth).
template <class Loaded>
NodalLoads kirsch_tractions(const Kirsch& k, const ZonedBlock& block, Loaded loaded) {
  NodalLoads loads;
  const std::vector<int>& loop = block.boundary()[0];
  const std::vector<Vec2>& x = block.positions();
  const double gauss[3][2] = {{0.5 - 0.5 * std::sqrt(0.6), 5.0 / 18},
                              {0.5, 8.0 / 18},
                              {0.5 + 0.5 * std::sqrt(0.6), 5.0 / 18}};
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const int na = loop[i], nb = loop[(i + 1) % loop.size()];
    const Vec2 &xa = x[na], &xb = x[nb];
    if (!loaded(xa, xb)) continue;
    const double length = (xb - xa).norm();
    const Vec2 n = Vec2(xb.y() - xa.y(), xa.x() - xb.x()) / length;
    Vec2 fa = Vec2::Zero(), fb = Vec2::Zero();
    for (const auto& [xi, weight] : gauss) {
      const ZoneStress s = k.stress(xa + xi * (xb - xa));
      const Vec2 t(s.xx * n.x() + s.xy * n.y(), s.xy * n.x() + s.yy * n.y());
      fa += weight * length * (1 - xi) * t;
      fb += weight * length * xi * t;
    }
    loads.emplace_back(na, fa);
    loads.emplace_back(nb, fb);
  }
  return loads;
}

/// sigma_thetatheta = t.sigma.t.
double hoop(const ZoneStress& s, const Vec2& t) {
  return s.xx * t.x() * t.x() + 2 * s.xy * t.x() * t.y() + s.yy * t.y() * t.y();
}

/// Brings the quarter plate to rest under the tractions (rollers on the
/// axes) and measures it against Kirsch.
KirschResult solve_kirsch(const Kirsch& k, ZonedBlock& block, const NodalLoads& loads) {
  const double a = k.a;
  const std::vector<Vec2> start = block.positions();
  int top = -1;
  for (int n = 0; n < block.n_nodes(); ++n) {
    block.fix(n, start[n].x() == 0, start[n].y() == 0);
    if (start[n] == Vec2(0, a)) top = n;
  }
  KirschResult r;
  r.zones = block.n_zones();
  r.steps = settle(block, loads, kPlateRatio, 100000);
  // The zones with an edge on the hole: their hoop stress (along the edge)
  // against the exact one at their centroid.
  double sum = 0;
  int count = 0;
  for (int z = 0; z < block.n_zones(); ++z) {
    const auto& t = block.zones()[z];
    for (int e = 0; e < 3; ++e) {
      const Vec2 &p = start[t[e]], &q = start[t[(e + 1) % 3]];
      if (std::abs(p.norm() - a) > 1e-9 * a || std::abs(q.norm() - a) > 1e-9 * a) continue;
      const Vec2 tangent = (q - p).normalized();
      const Vec2 c = (start[t[0]] + start[t[1]] + start[t[2]]) / 3;
      const double err =
          (hoop(block.stress(z), tangent) - hoop(k.stress(c), tangent)) / (3 * k.sigma0);
      sum += err * err;
      ++count;
    }
  }
  r.hoop_rms = std::sqrt(sum / count);
  r.top_error = std::abs((block.positions()[top].y() - a) / k.hole_top_displacement() - 1);
  return r;
}

/// A structured quarter ring a <= r <= 4 a: n zones' widths along the
/// hole, rings growing geometrically so that the zones stay about square,
/// each quadrilateral (ring i, sector j: zones 2 (i n + j) and the next)
/// cut along alternating diagonals.
ZoneMesh polar_mesh(double a, int n) {
  const double grow = 1 + 0.5 * std::numbers::pi / n;
  const int rings = static_cast<int>(std::ceil(std::log(4.0) / std::log(grow)));
  ZoneMesh m;
  auto node = [&](int i, int j) { return i * (n + 1) + j; };  // ring i, angle j
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= n; ++j) {
      const double r = a * std::pow(4.0, double(i) / rings), t = 0.5 * std::numbers::pi * j / n;
      // Exact zeros on the axes, where the rollers are.
      m.nodes.emplace_back(j == n ? 0.0 : r * std::cos(t), j == 0 ? 0.0 : r * std::sin(t));
    }
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < n; ++j) {
      const int p = node(i, j), q = node(i + 1, j), r = node(i + 1, j + 1), s = node(i, j + 1);
      if ((i + j) % 2 == 0) {
        m.zones.push_back({p, q, r});
        m.zones.push_back({p, r, s});
      } else {
        m.zones.push_back({p, q, s});
        m.zones.push_back({q, r, s});
      }
    }
  std::vector<int> loop;
  for (int i = 0; i < rings; ++i) loop.push_back(node(i, 0));  // y = 0, outwards
  for (int j = 0; j < n; ++j) loop.push_back(node(rings, j));  // the outer arc
  for (int i = rings; i > 0; --i) loop.push_back(node(i, n));  // x = 0, inwards
  for (int j = n; j > 0; --j) loop.push_back(node(0, j));      // the hole, clockwise
  m.boundary = {loop};
  m.corner_nodes = {node(0, 0), node(rings, 0), node(rings, n), node(0, n)};
  return m;
}

/// The hoop stress concentration at the hole's top from the polar mesh: the
/// two zones of each of the first two rings' last sector averaged (the
/// quadrilateral's stress at its centre), their hoop stress along the
/// sector's mid-angle theta_c extrapolated linearly to r = a, relative to
/// Kirsch's sigma_0 (1 - 2 cos 2 theta_c) there (3 sigma_0 at the top).
double concentration_error(const Kirsch& k, const ZonedBlock& block, int n) {
  const double tc = 0.5 * std::numbers::pi * (1 - 0.5 / n);
  const Vec2 tangent(-std::sin(tc), std::cos(tc));
  double value[2], radius[2];
  for (int i = 0; i < 2; ++i) {
    const int quad = i * n + (n - 1);
    ZoneStress mean;
    double area = 0;
    Vec2 centre = Vec2::Zero();
    for (int z : {2 * quad, 2 * quad + 1}) {
      const auto& t = block.zones()[z];
      const std::vector<Vec2>& x = block.positions();
      const double w = 0.5 * orient(x[t[0]], x[t[1]], x[t[2]]);
      const ZoneStress s = block.stress(z);
      mean.xx += w * s.xx;
      mean.yy += w * s.yy;
      mean.xy += w * s.xy;
      centre += w * (x[t[0]] + x[t[1]] + x[t[2]]) / 3;
      area += w;
    }
    mean = {mean.xx / area, mean.yy / area, mean.xy / area, 0};
    radius[i] = (centre / area).norm();
    value[i] = hoop(mean, tangent);
  }
  const double at_hole =
      value[0] + (value[0] - value[1]) * (radius[0] - k.a) / (radius[1] - radius[0]);
  const double exact = k.sigma0 * (1 - 2 * std::cos(2 * tc));
  return std::abs(at_hole / exact - 1);
}

TEST(DemZonedStatics, KirschHoopStressConcentrationConverges) {
  const Kirsch k{1, 1e6, {10e9, 0.25, 2500}};
  std::vector<double> concentration, top;
  for (int n : {6, 12, 24}) {
    ZonedBlock block(polar_mesh(k.a, n), k.rock);
    const double outer = 4 * k.a * (1 - 1e-9);
    const NodalLoads loads = kirsch_tractions(k, block, [&](const Vec2& p, const Vec2& q) {
      return p.norm() > outer && q.norm() > outer;
    });
    const KirschResult r = solve_kirsch(k, block, loads);
    ASSERT_LE(r.steps, 100000);
    concentration.push_back(concentration_error(k, block, n));
    top.push_back(r.top_error);
    std::printf(
        "Kirsch, %2d zones along the quarter hole: %4d zones, %5d steps; hoop stress "
        "concentration error %.3e, hole top displacement %.3e (zones on the hole: "
        "hoop stress RMS error %.3e)\n",
        n, r.zones, r.steps, concentration.back(), top.back(), r.hoop_rms);
  }
  for (std::size_t i = 1; i < top.size(); ++i) {
    const double p_stress = std::log2(concentration[i - 1] / concentration[i]);
    const double p_top = std::log2(top[i - 1] / top[i]);
    std::printf("observed order: concentration %.2f, displacement %.2f\n", p_stress, p_top);
    // Stresses: constant in a zone, first order; averaged over the
    // quadrilateral and extrapolated, up to second (observed 1.5).
    EXPECT_GT(p_stress, 1.0);
    EXPECT_LT(p_stress, 2.5);
    // Nodal displacements of linear zones: second order.
    EXPECT_GT(p_top, 1.6);
    EXPECT_LT(p_top, 2.4);
  }
  // The finest errors: what first order predicts from the middle one, at most.
  EXPECT_LT(concentration[2], 0.5 * concentration[1]);
  EXPECT_LT(top[2], 0.25 * top[1] * 1.3);
}

/// A quarter of a square plate of half-width 3 a with the hole, meshed by
/// the block mesher: zones of h at the hole growing linearly to 4 h at the
/// outer sides.
ZonedBlock meshed_plate(const Kirsch& k, double h, VolumetricStrain formulation) {
  const double a = k.a, half = 3 * a;
  const int n_arc = static_cast<int>(std::ceil(0.5 * std::numbers::pi * a / h));
  std::vector<Vec2> outline = {{a, 0}, {half, 0}, {half, half}, {0, half}, {0, a}};
  for (int i = n_arc - 1; i > 0; --i) {
    const double t = 0.5 * std::numbers::pi * i / n_arc;
    outline.emplace_back(a * std::cos(t), a * std::sin(t));
  }
  const SizeFunction size = [&](const Vec2& x) {
    return h * std::min(4.0, 1 + 3 * (x.norm() - a) / (half - a));
  };
  ZonedBlock block(mesh_block(Polygon(outline), size), k.rock, formulation);
  return block;
}

TEST(DemZonedStatics, KirschNearlyIncompressibleNeedsTheNodalAverage) {
  const Kirsch k{1, 1e6, {10e9, 0.49, 2500}};
  KirschResult r[2];
  for (VolumetricStrain f : {VolumetricStrain::NodalAverage, VolumetricStrain::PerZone}) {
    ZonedBlock block = meshed_plate(k, k.a / 8, f);
    const NodalLoads loads = kirsch_tractions(k, block, [&](const Vec2& p, const Vec2& q) {
      return (p.x() == 3 * k.a && q.x() == 3 * k.a) || (p.y() == 3 * k.a && q.y() == 3 * k.a);
    });
    KirschResult& result = r[f == VolumetricStrain::PerZone];
    result = solve_kirsch(k, block, loads);
    ASSERT_LE(result.steps, 100000);
    std::printf(
        "Kirsch, nu = 0.49, %s: %d zones, %d steps; hoop stress RMS error on the hole "
        "%.3e, hole top displacement %.3e\n",
        f == VolumetricStrain::PerZone ? "plain constant strain" : "nodal average", result.zones,
        result.steps, result.hoop_rms, result.top_error);
  }
  // The nodal average as good as at nu = 0.25 (1.3 % and 1.7 % on this
  // mesh); the plain triangles lock: stiffer, and their pressure
  // oscillates from zone to zone.
  EXPECT_LT(r[0].hoop_rms, 0.05);
  EXPECT_LT(r[0].top_error, 0.025);
  EXPECT_GT(r[1].hoop_rms, 4 * r[0].hoop_rms);
  EXPECT_GT(r[1].top_error, 2 * r[0].top_error);
}

}  // namespace
}  // namespace fissure::dem

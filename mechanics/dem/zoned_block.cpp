#include "mechanics/dem/zoned_block.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/errors.h"

namespace fissure::dem {

double ZoneMaterial::p_wave_speed() const {
  return std::sqrt(constrained() / density);
}

namespace {

/// Twice the signed area of zone (a, b, c).
double twice_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
}

/// The highest squared frequency of one constant-strain triangle with a
/// third of its mass at each node: omega^2 = lambda_max(M_z^-1 K_z), the
/// nonzero eigenvalues of (3 / rho) B^T D B being those of the 3 x 3
/// (3 / rho) L^T (B B^T) L, with D = L L^T.
double zone_frequency_squared(const Vec2& a, const Vec2& b, const Vec2& c, const Eigen::Matrix3d& l,
                              double density) {
  const double two_a = twice_area(a, b, c);
  const Vec2* p[3] = {&a, &b, &c};
  Eigen::Matrix3d bbt = Eigen::Matrix3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const Vec2 &q = *p[(k + 1) % 3], &r = *p[(k + 2) % 3];
    const double gx = (q.y() - r.y()) / two_a, gy = (r.x() - q.x()) / two_a;  // grad N_k
    Eigen::Matrix<double, 3, 2> bk;
    bk << gx, 0, 0, gy, gy, gx;
    bbt += bk * bk.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(l.transpose() * bbt * l, Eigen::EigenvaluesOnly);
  return 3 / density * eig.eigenvalues().maxCoeff();
}

}  // namespace

ZonedBlock::ZonedBlock(ZoneMesh mesh, const ZoneMaterial& material, VolumetricStrain volumetric)
    : material_(material),
      volumetric_(volumetric),
      zones_(std::move(mesh.zones)),
      boundary_(std::move(mesh.boundary)),
      corner_nodes_(std::move(mesh.corner_nodes)),
      position_(std::move(mesh.nodes)) {
  FISSURE_CHECK(material.young > 0 && std::isfinite(material.young), Error,
                "Young's modulus " << material.young << " Pa: expected a positive value");
  FISSURE_CHECK(material.poisson > -1 && material.poisson < 0.5, Error,
                "Poisson's ratio " << material.poisson << ": expected a value in (-1, 0.5)");
  FISSURE_CHECK(material.density > 0 && std::isfinite(material.density), Error,
                "density " << material.density << " kg/m^3: expected a positive value");
  bulk_ = material.bulk();
  shear_ = material.shear();
  const std::size_t n = position_.size();
  velocity_.assign(n, Vec2::Zero());
  external_.assign(n, Vec2::Zero());
  contact_.assign(n, Vec2::Zero());
  internal_.assign(n, Vec2::Zero());
  mass_.assign(n, 0.0);
  fixed_.assign(n, 0);
  pressure_.assign(n, 0.0);
  volume_.assign(n, 0.0);
  volume_change_.assign(n, 0.0);
  applied_.assign(n, 0.0);
  deviator_.assign(zones_.size(), {});
  zone_pressure_.assign(zones_.size(), 0.0);
  area_.assign(zones_.size(), 0.0);

  // D = L L^T, plane strain, (xx, yy, engineering xy).
  const double lambda = bulk_ - 2 * shear_ / 3;
  Eigen::Matrix3d d;
  d << lambda + 2 * shear_, lambda, 0, lambda, lambda + 2 * shear_, 0, 0, 0, shear_;
  const Eigen::Matrix3d l = d.llt().matrixL();
  double omega2 = 0;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const auto& t = zones_[z];
    for (int a : t)
      FISSURE_CHECK(a >= 0 && a < static_cast<int>(n), Error,
                    "zone " << z << " names node " << a << " of " << n);
    const Vec2 &a = position_[t[0]], &b = position_[t[1]], &c = position_[t[2]];
    area_[z] = 0.5 * twice_area(a, b, c);
    FISSURE_CHECK(area_[z] > 0, GeometryError,
                  "zone " << z << " has area " << area_[z] << " m^2: expected counter-clockwise "
                          << "zones with positive area");
    for (int a : t) {
      volume_[a] += area_[z] / 3;
      mass_[a] += material.density * area_[z] / 3;
    }
    omega2 = std::max(omega2, zone_frequency_squared(a, b, c, l, material.density));
  }
  for (std::size_t a = 0; a < n; ++a)
    FISSURE_CHECK(mass_[a] > 0, Error, "node " << a << " belongs to no zone");
  critical_step_ = omega2 > 0 ? 2 / std::sqrt(omega2) : std::numeric_limits<double>::infinity();
}

Polygon ZonedBlock::boundary_polygon() const {
  Polygon p;
  for (const std::vector<int>& loop : boundary_) {
    for (int a : loop) p.vertices.push_back(position_[a]);
    p.loop_offsets.push_back(p.n_vertices());
  }
  return p;
}

void ZonedBlock::fix(int node, bool x, bool y) {
  fixed_[node] = static_cast<std::uint8_t>((x ? 1 : 0) | (y ? 2 : 0));
}

void ZonedBlock::set_stress(const ZoneStress& s) {
  const double mean = (s.xx + s.yy + s.zz) / 3;
  for (Deviator& d : deviator_) d = {s.xx - mean, s.yy - mean, s.xy, s.zz - mean};
  std::fill(pressure_.begin(), pressure_.end(), mean);
  std::fill(zone_pressure_.begin(), zone_pressure_.end(), mean);
}

void ZonedBlock::scale_about(const Vec2& centre, double factor) {
  for (Vec2& x : position_) x = centre + factor * (x - centre);
}

void ZonedBlock::stop() {
  // The motion a stop takes away (a quasi-static solve's) counts as damped.
  energy_.dissipated += energy_.kinetic;
  energy_.kinetic = 0;
  for (std::size_t a = 0; a < velocity_.size(); ++a)
    for (int i = 0; i < 2; ++i)
      if (!(fixed_[a] & (1 << i))) velocity_[a](i) = 0;
}

ZoneStress ZonedBlock::mean_stress() const {
  ZoneStress mean;
  double area = 0;
  for (int z = 0; z < n_zones(); ++z) {
    const ZoneStress s = stress(z);
    mean.xx += area_[z] * s.xx;
    mean.yy += area_[z] * s.yy;
    mean.xy += area_[z] * s.xy;
    mean.zz += area_[z] * s.zz;
    area += area_[z];
  }
  if (area > 0) mean = {mean.xx / area, mean.yy / area, mean.xy / area, mean.zz / area};
  return mean;
}

Vec2 ZonedBlock::centre_of_mass() const {
  Vec2 sum = Vec2::Zero();
  double m = 0;
  for (std::size_t a = 0; a < position_.size(); ++a) {
    sum += mass_[a] * position_[a];
    m += mass_[a];
  }
  return sum / m;
}

Eigen::Vector3d ZonedBlock::mean_motion(const Vec2& c) const {
  Vec2 momentum = Vec2::Zero();
  double m = 0, angular = 0, inertia = 0;
  for (std::size_t a = 0; a < position_.size(); ++a) {
    const Vec2 r = position_[a] - c;
    momentum += mass_[a] * velocity_[a];
    m += mass_[a];
    angular += mass_[a] * cross(r, velocity_[a]);
    inertia += mass_[a] * r.squaredNorm();
  }
  const Vec2 v = momentum / m;
  return {v.x(), v.y(), inertia > 0 ? angular / inertia : 0.0};
}

ZoneStress ZonedBlock::stress(int zone) const {
  const Deviator& d = deviator_[zone];
  double mean = zone_pressure_[zone];
  if (volumetric_ == VolumetricStrain::NodalAverage) {
    const auto& t = zones_[zone];
    mean = (pressure_[t[0]] + pressure_[t[1]] + pressure_[t[2]]) / 3;
  }
  return {d.xx + mean, d.yy + mean, d.xy, d.zz + mean};
}

void ZonedBlock::update_stresses(double dt, double stiffness_damping) {
  const bool nodal = volumetric_ == VolumetricStrain::NodalAverage;
  // Rayleigh's stiffness-proportional part: beta times the elastic stress
  // rate, the step's increments over dt (none before the first step).
  const bool viscous = stiffness_damping > 0 && dt > 0;
  const double rate = viscous ? stiffness_damping / dt : 0.0;
  if (viscous)
    viscous_stress_.assign(zones_.size(), Eigen::Vector3d::Zero());
  else
    viscous_stress_.clear();
  if (nodal) {
    std::fill(volume_.begin(), volume_.end(), 0.0);
    std::fill(volume_change_.begin(), volume_change_.end(), 0.0);
  }
  const double two_g = 2 * shear_;
  const double half_dt = 0.5 * dt;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const auto& t = zones_[z];
    const Vec2 &va = velocity_[t[0]], &vb = velocity_[t[1]], &vc = velocity_[t[2]];
    // The increment's midpoint geometry x^{n-1/2} = x^n - v^{n-1/2} dt / 2
    // (Hughes and Winget 1980): a rigid turn of any size then gives no
    // strain, and the Cayley rotation below is exactly the turn.
    const Vec2 xa = position_[t[0]] - half_dt * va, xb = position_[t[1]] - half_dt * vb,
               xc = position_[t[2]] - half_dt * vc;
    const double two_a = twice_area(xa, xb, xc);
    area_[z] = 0.5 * twice_area(position_[t[0]], position_[t[1]], position_[t[2]]);  // at x^n
    // 2A grad N_k = (y_{k+1} - y_{k+2}, x_{k+2} - x_{k+1}).
    const double s = dt / two_a;
    const double bx0 = xb.y() - xc.y(), bx1 = xc.y() - xa.y(), bx2 = xa.y() - xb.y();
    const double by0 = xc.x() - xb.x(), by1 = xa.x() - xc.x(), by2 = xb.x() - xa.x();
    const double dux_dx = s * (va.x() * bx0 + vb.x() * bx1 + vc.x() * bx2);
    const double dux_dy = s * (va.x() * by0 + vb.x() * by1 + vc.x() * by2);
    const double duy_dx = s * (va.y() * bx0 + vb.y() * bx1 + vc.y() * bx2);
    const double duy_dy = s * (va.y() * by0 + vb.y() * by1 + vc.y() * by2);
    const double volumetric = dux_dx + duy_dy;

    // Jaumann, objectively: the material turns by beta = 2 atan(theta / 2),
    // theta = (du_y/dx - du_x/dy) / 2 (Cayley: cos and sin without
    // trigonometry, c^2 + s^2 = 1), and the in-plane deviator ((xx - yy) / 2,
    // xy) by 2 beta.
    Deviator& d = deviator_[z];
    const double h = 0.25 * (duy_dx - dux_dy), q = 1 / (1 + h * h);
    const double c = (1 - h * h) * q, sn = 2 * h * q;
    const double cos2 = c * c - sn * sn, sin2 = 2 * sn * c;
    const double half_sum = 0.5 * (d.xx + d.yy), half_diff = 0.5 * (d.xx - d.yy);
    const double diff = half_diff * cos2 - d.xy * sin2;
    const double xy = half_diff * sin2 + d.xy * cos2;
    const double third = volumetric / 3;
    d.xx = half_sum + diff + two_g * (dux_dx - third);
    d.yy = half_sum - diff + two_g * (duy_dy - third);
    d.xy = xy + shear_ * (dux_dy + duy_dx);
    d.zz += two_g * -third;
    if (viscous) {
      // The deviatoric rate here, the volumetric one below (per zone or
      // from the nodes' pressure rates).
      viscous_stress_[z] =
          rate * Eigen::Vector3d(two_g * (dux_dx - third), two_g * (duy_dy - third),
                                 shear_ * (dux_dy + duy_dx));
      if (!nodal) viscous_stress_[z].head<2>().array() += rate * bulk_ * volumetric;
    }

    if (nodal) {
      const double v = area_[z] / 3, dv = v * volumetric;
      for (int a : t) {
        volume_[a] += v;
        volume_change_[a] += dv;
      }
    } else {
      zone_pressure_[z] += bulk_ * volumetric;
    }
  }
  if (nodal)
    for (std::size_t a = 0; a < pressure_.size(); ++a)
      if (volume_[a] > 0) pressure_[a] += bulk_ * volume_change_[a] / volume_[a];
  if (viscous && nodal)
    for (std::size_t z = 0; z < zones_.size(); ++z) {
      double mean = 0;
      for (int a : zones_[z])
        if (volume_[a] > 0) mean += bulk_ * volume_change_[a] / volume_[a] / 3;
      viscous_stress_[z].head<2>().array() += rate * mean;
    }
}

void ZonedBlock::add_internal_forces() {
  const bool nodal = volumetric_ == VolumetricStrain::NodalAverage;
  const bool viscous = !viscous_stress_.empty();
  std::fill(internal_.begin(), internal_.end(), Vec2::Zero());
  std::fill(applied_.begin(), applied_.end(), 0.0);
  if (viscous)
    viscous_force_.assign(position_.size(), Vec2::Zero());
  else
    viscous_force_.clear();
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const auto& t = zones_[z];
    const Deviator& d = deviator_[z];
    const double mean =
        nodal ? (pressure_[t[0]] + pressure_[t[1]] + pressure_[t[2]]) / 3 : zone_pressure_[z];
    const double sxx = d.xx + mean, syy = d.yy + mean, sxy = d.xy;
    // f_k = -A sigma grad N_k = -sigma (2A grad N_k) / 2.
    for (int k = 0; k < 3; ++k) {
      const Vec2 &q = position_[t[(k + 1) % 3]], &r = position_[t[(k + 2) % 3]];
      const double nx = 0.5 * (q.y() - r.y()), ny = 0.5 * (r.x() - q.x());
      Vec2 f(-(sxx * nx + sxy * ny), -(sxy * nx + syy * ny));
      if (viscous) {
        const Eigen::Vector3d& v = viscous_stress_[z];
        const Vec2 fv(-(v(0) * nx + v(2) * ny), -(v(2) * nx + v(1) * ny));
        viscous_force_[t[k]] += fv;
        f += fv;
      }
      internal_[t[k]] += f;
      applied_[t[k]] += f.norm();
    }
  }
}

void ZonedBlock::move_nodes(double dt, const Vec2& gravity, const DampingControls& damping) {
  double kinetic = 0, dissipated = 0, work = 0, largest = 0, applied = 0;
  double gravity_work = 0, contact_work = 0;
  const bool damped = damping.local > 0 || damping.mass > 0;
  const bool viscous = !viscous_force_.empty();
  for (std::size_t a = 0; a < position_.size(); ++a) {
    const double m = mass_[a];
    const double inertial = inertial_.empty() ? m : inertial_[a];
    const Vec2 weight = m * gravity;
    const Vec2 outside = external_[a] + weight;
    const Vec2 force = outside + internal_[a];
    applied += applied_[a] + outside.norm();
    Vec2& v = velocity_[a];
    Vec2 unbalanced = Vec2::Zero();
    for (int i = 0; i < 2; ++i) {
      if (fixed_[a] & (1 << i)) {
        // Held: the support's reaction cancels the whole force, so what the
        // outside does on the block here (applied forces and reaction) is
        // minus the zones' force times the velocity.
        work -= internal_[a](i) * v(i) * dt;
        gravity_work += weight(i) * v(i) * dt;
        contact_work += contact_[a](i) * v(i) * dt;
        if (viscous) dissipated -= viscous_force_[a](i) * v(i) * dt;
        kinetic += 0.5 * m * v(i) * v(i);
        continue;
      }
      unbalanced(i) = force(i);
      const double before =
          started_ ? v(i) : velocity_before_first_step(v(i), force(i), inertial, dt);
      const double after = next_velocity(before, force(i), inertial, dt, damping);
      const double mean = 0.5 * (before + after);
      kinetic += 0.5 * m * mean * mean;
      work += outside(i) * mean * dt;
      gravity_work += weight(i) * mean * dt;
      contact_work += contact_[a](i) * mean * dt;
      // What the damping took: the work of the undamped force less the
      // change of the kinetic energy, F v dt - m (v+ - v-) v (m the
      // inertial mass); and what the zones' dashpots took, -f_v v dt.
      if (damped) dissipated += (force(i) * dt - inertial * (after - before)) * mean;
      if (viscous) dissipated -= viscous_force_[a](i) * mean * dt;
      v(i) = after;
    }
    largest = std::max(largest, unbalanced.norm());
    position_[a] += v * dt;
    external_[a].setZero();
    contact_[a].setZero();
  }
  // The works' first share is halved (its half before t^0 belongs to the
  // fictitious v^{-1/2}), the damping's whole (dem_energy.h, CycleSum).
  const double first = started_ ? 1.0 : 0.5;
  energy_.kinetic = kinetic;
  energy_.dissipated += dissipated;
  energy_.external_work += first * work;
  energy_.gravity_work += first * gravity_work;
  energy_.contact_work += first * contact_work;
  last_dissipated_ = dissipated;
  last_external_work_ = work;
  last_gravity_work_ = gravity_work;
  last_contact_work_ = contact_work;
  unbalanced_ = {largest, position_.empty() ? 0.0 : applied / position_.size()};
  started_ = true;
}

void ZonedBlock::update_zones(double dt, double stiffness_damping) {
  // Before the first step the velocities are v^0, not a half step's: no
  // strain increment (the zones' areas are still updated).
  update_stresses(started_ ? dt : 0.0, stiffness_damping);
  add_internal_forces();
}

void ZonedBlock::step(double dt, const Vec2& gravity, const DampingControls& damping,
                      double stiffness_damping) {
  update_zones(dt, stiffness_damping);
  move_nodes(dt, gravity, damping);
}

double ZonedBlock::strain_energy() const {
  double u = 0;
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    const Deviator& d = deviator_[z];
    const double dd = d.xx * d.xx + d.yy * d.yy + d.zz * d.zz + 2 * d.xy * d.xy;
    u += area_[z] * dd / (4 * shear_);
    if (volumetric_ == VolumetricStrain::PerZone)
      u += area_[z] * zone_pressure_[z] * zone_pressure_[z] / (2 * bulk_);
  }
  if (volumetric_ == VolumetricStrain::NodalAverage)
    for (std::size_t a = 0; a < pressure_.size(); ++a)
      u += volume_[a] * pressure_[a] * pressure_[a] / (2 * bulk_);
  return u;
}

EnergyBalance ZonedBlock::energy() const {
  EnergyBalance e = energy_;
  if (!started_) {
    e.kinetic = 0;
    for (std::size_t a = 0; a < velocity_.size(); ++a)
      e.kinetic += 0.5 * mass_[a] * velocity_[a].squaredNorm();
  }
  // The last step's work is shared between the two half steps around t^n.
  e.dissipated -= 0.5 * last_dissipated_;
  e.external_work -= 0.5 * last_external_work_;
  e.gravity_work -= 0.5 * last_gravity_work_;
  e.contact_work -= 0.5 * last_contact_work_;
  e.strain = strain_energy();
  return e;
}

}  // namespace fissure::dem

// A reference for 1D consolidation with a stress-dependent permeability: a
// fine finite-volume solution of the nonlinear diffusion equation (no closed
// form exists once k depends on p). Independent of the model's code, so that
// a mistake there cannot hide in the reference. SI units.
//
//   column 0 <= y <= H (y up), impermeable bottom (dp/dy = 0 at y = 0),
//   drained top (p(H, t) = 0 for t > 0), p(y, 0+) = p_u,
//   S dp/dt = d/dy( (k(p) / mu) dp/dy ),
//   sigma(p) = a + b p (compression positive), s = max(sigma, 0),
//   k(p) = k_ref exp(-beta (s - sigma_ref)).
//
// Scheme: cell-centred finite volumes on uniform cells, variable-step BDF2 in
// time (backward Euler for the first step), each step solved by Newton's
// method with the exact tridiagonal Jacobian (Thomas algorithm).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace fissure::test {

struct NonlinearConsolidation {
  double height = 10;               // H, m
  double storage = 1e-10;           // S, 1/Pa
  double viscosity = 1e-3;          // mu, Pa s
  double undrained_pressure = 1e6;  // p_u, Pa
  double k_ref = 1e-15;             // m^2
  double beta = 0;                  // 1/Pa
  double sigma_ref = 0;             // Pa
  double a = 0, b = 0;              // sigma(p) = a + b p, Pa and -
};

/// k(p) = k_ref exp(-beta (max(a + b p, 0) - sigma_ref)).
inline double nonlinear_consolidation_permeability(const NonlinearConsolidation& c, double p) {
  return c.k_ref * std::exp(-c.beta * (std::max(c.a + c.b * p, 0.0) - c.sigma_ref));
}

/// T_c = H^2 S mu / k_ref: the time unit of the verification (T = t / T_c).
inline double nonlinear_consolidation_time(const NonlinearConsolidation& c) {
  return c.height * c.height * c.storage * c.viscosity / c.k_ref;
}

/// Time steps, in units of T_k = H^2 S mu / k_max (k_max = the larger of k(0) and
/// k(p_u): p stays between 0 and p_u and k is monotonic in p, so T_k is the fastest time
/// scale). dt_n = min(first growth^n, cap) T_k, the first step at most 1e-3 t; the
/// last one or two steps shortened to end exactly at t. While the steps grow, the
/// solution near the top is the similarity layer of the initial jump and BDF2's error
/// goes as (dt / t)^2 ~ (growth - 1)^2: growth 1.005 keeps it near 2e-6 p_u (1.02 left
/// 2.5e-5 p_u at t = 0.05 T_c); the cap bounds the error of the late, slow decay
/// (about 5e-7 p_u at T_k). About 2200 steps to 1 T_k, 3200 to 2 T_k.
struct NonlinearConsolidationSteps {
  double first = 1e-6, growth = 1.005, cap = 1e-3;
};

/// p at the heights `y` (each in [0, H]) at time t > 0.
inline std::vector<double> nonlinear_consolidation_pressure(
    const NonlinearConsolidation& c, double t, const std::vector<double>& y, int cells = 2000,
    const NonlinearConsolidationSteps& steps = {}) {
  if (!(c.height > 0 && c.storage > 0 && c.viscosity > 0 && c.k_ref > 0 && t > 0 && cells >= 2 &&
        steps.first > 0 && steps.growth >= 1 && steps.cap > 0))
    throw std::invalid_argument("nonlinear_consolidation_pressure: bad parameters");
  for (double yi : y)
    if (!(yi >= 0 && yi <= c.height))
      throw std::invalid_argument("nonlinear_consolidation_pressure: y outside [0, H]");

  const int n = cells;
  const double h = c.height / n, mu = c.viscosity, pu = c.undrained_pressure;
  const double k_max = std::max(nonlinear_consolidation_permeability(c, 0),
                                nonlinear_consolidation_permeability(c, pu));
  const double tk = c.height * c.height * c.storage * mu / k_max;

  // Face value q = (1 / (mu d)) int_{p_lo}^{p_hi} k(p) dp, d the distance between the
  // two pressures, and its derivatives -k(p_lo) / (mu d), k(p_hi) / (mu d) (k_lo, k_hi
  // given: each cell's k is computed once per Newton iteration). This is
  // the Kirchhoff form of the two-point flux: (k / mu) dp/dy = d/dy (phi / mu),
  // phi(p) = int k dp, so the face mobility is the mean of k over [p_lo, p_hi], and
  // the flux is exact for steady 1D flow. It is second order like the alternatives
  // (k at the face's mean pressure, its midpoint rule, or the harmonic mean of the two
  // cells' k: both O(h^2) off the mean), but with no error from the variation of k
  // between the cells: in the verification's case (beta = 2e-6, b = -1) the cell
  // values' error was 4x smaller than with k at the mean pressure. The same rule
  // serves the top half-cell face (p_hi = 0, d = h / 2). Integral: k = k(u) e^{g (p - u)},
  // g = -beta b, where sigma > 0 and constant where sigma <= 0, split at the kink
  // sigma = 0; expm1 keeps it accurate for g (v - u) -> 0.
  const double g = -c.beta * c.b;
  const double kink = c.b != 0 ? -c.a / c.b : 0;  // sigma(kink) = 0 (if b != 0)
  const double k_kink = nonlinear_consolidation_permeability(c, kink);
  auto integral_smooth = [&](double u, double v, double ku) {  // u, v on one side of the kink
    const double x = g * (v - u);
    const bool stressed = c.a + c.b * 0.5 * (u + v) > 0;
    return ku * (v - u) * (stressed && x != 0 ? std::expm1(x) / x : 1.0);
  };
  struct Face {
    double q, dlo, dhi;
  };
  auto face = [&](double lo, double hi, double k_lo, double k_hi, double d) {
    const double integral =
        c.b != 0 && (kink - lo) * (kink - hi) < 0
            ? integral_smooth(lo, kink, k_lo) + integral_smooth(kink, hi, k_kink)
            : integral_smooth(lo, hi, k_lo);
    return Face{integral / (mu * d), -k_lo / (mu * d), k_hi / (mu * d)};
  };

  // p: the iterate of p^{n+1}; p1, p2: p^n, p^{n-1}.
  std::vector<double> p(n, pu), p1(n, pu), p2(n, pu), k(n), r(n), lower(n), diag(n), upper(n);
  const double k_top = nonlinear_consolidation_permeability(c, 0);
  double time = 0, dt_prev = 0, nominal = std::min(steps.first * tk, 1e-3 * t);
  const double tol = 1e-12 * std::max(std::abs(pu), 1e-300);
  while (time < t) {
    // Step: the nominal one, or the rest (one step, or two halves if the rest is
    // under two nominal steps, so that the step ratio stays <= growth).
    const double rest = t - time;
    const double dt = rest <= nominal * (1 + 1e-12) ? rest
                      : rest < 2 * nominal          ? 0.5 * rest
                                                    : nominal;
    // Variable-step BDF2, w = dt / dt_prev:
    //   (a0 p^{n+1} + a1 p^n + a2 p^{n-1}) / dt = dp/dt at t^{n+1} + O(dt^2),
    //   a0 = (1 + 2w) / (1 + w), a1 = -(1 + w), a2 = w^2 / (1 + w);
    // backward Euler (a0 = 1, a1 = -1, a2 = 0) for the first step.
    const double w = dt_prev > 0 ? dt / dt_prev : 0;
    const double a0 = (1 + 2 * w) / (1 + w), a1 = -(1 + w), a2 = w * w / (1 + w);
    // Predictor: linear extrapolation from p^{n-1}, p^n.
    for (int i = 0; i < n; ++i) p[i] = p1[i] + w * (p1[i] - p2[i]);

    // Newton on R_i = (S h / dt) (a0 p_i + a1 p^n_i + a2 p^{n-1}_i) - (q_{i+1/2} - q_{i-1/2}),
    // q_{-1/2} = 0 (impermeable bottom), q_{n-1/2} the half-cell face to p = 0 at y = H.
    const double m = c.storage * h / dt;
    for (int iter = 0;; ++iter) {
      if (iter == 50) throw std::runtime_error("nonlinear_consolidation_pressure: no convergence");
      for (int i = 0; i < n; ++i) {
        r[i] = m * (a0 * p[i] + a1 * p1[i] + a2 * p2[i]);
        diag[i] = m * a0;
        lower[i] = upper[i] = 0;
        k[i] = nonlinear_consolidation_permeability(c, p[i]);
      }
      for (int i = 0; i < n; ++i) {  // face i + 1/2, between cells i and i + 1 (or the top)
        const bool top = i == n - 1;
        const Face f =
            top ? face(p[i], 0.0, k[i], k_top, 0.5 * h) : face(p[i], p[i + 1], k[i], k[i + 1], h);
        r[i] -= f.q;  // outflow of cell i
        diag[i] -= f.dlo;
        if (!top) {
          upper[i] -= f.dhi;
          r[i + 1] += f.q;  // inflow of cell i + 1
          diag[i + 1] += f.dhi;
          lower[i + 1] += f.dlo;
        }
      }
      // Thomas algorithm for J dp = -R (J = lower/diag/upper), then p += dp.
      for (int i = 1; i < n; ++i) {
        const double f = lower[i] / diag[i - 1];
        diag[i] -= f * upper[i - 1];
        r[i] -= f * r[i - 1];
      }
      double change = 0;
      for (int i = n - 1; i >= 0; --i) {
        const double d = (-r[i] - (i + 1 < n ? upper[i] * r[i + 1] : 0.0)) / diag[i];
        r[i] = d;  // r now holds dp (r[i + 1] above was already dp_{i+1})
        p[i] += d;
        change = std::max(change, std::abs(d));
      }
      if (change <= tol) break;
    }
    p2.swap(p1);
    p1 = p;
    time = dt == rest ? t : time + dt;
    dt_prev = dt;
    nominal = std::min(nominal * steps.growth, steps.cap * tk);
  }

  // Quadratic (3-point Lagrange) interpolation through the nearest cell centre
  // y_m = (m + 1/2) h and its two neighbours among the nodes y_{-1} = -h/2 (mirror of
  // y_0, value p_0: the parabola then has dp/dy = 0 at y = 0), the cell centres, and
  // y_n = H (value 0). Not linear: near the drained top the flux k dp/dy is nearly
  // uniform while k grows with p, so p'' ~ (dk/dp / k) p'^2 is large, and linear
  // interpolation's h^2 p'' / 8 reached 3e-5 p_u at t = 0.01 T_c in the verification's
  // case (beta = 2e-6, b = -1), several times the error of the cell values.
  auto node_y = [&](int j) { return j == n ? c.height : (j + 0.5) * h; };
  auto node_p = [&](int j) { return j == n ? 0.0 : p1[std::max(j, 0)]; };
  std::vector<double> out;
  out.reserve(y.size());
  for (double yi : y) {
    const int m = std::clamp(static_cast<int>(std::lround(yi / h - 0.5)), 0, n - 1);
    const double x0 = node_y(m - 1), x1 = node_y(m), x2 = node_y(m + 1);
    out.push_back(node_p(m - 1) * (yi - x1) * (yi - x2) / ((x0 - x1) * (x0 - x2)) +
                  node_p(m) * (yi - x0) * (yi - x2) / ((x1 - x0) * (x1 - x2)) +
                  node_p(m + 1) * (yi - x0) * (yi - x1) / ((x2 - x0) * (x2 - x1)));
  }
  return out;
}

}  // namespace fissure::test

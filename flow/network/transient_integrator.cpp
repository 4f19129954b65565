#include "flow/network/transient_integrator.h"

#include <cmath>

#include "core/base/bdf2.h"
#include "core/base/errors.h"
#include "flow/network/cvode_integrator.h"

namespace fissure::flow {

using Scheme = TransientControls::Scheme;

TransientIntegrator::TransientIntegrator(const TransientControls& controls,
                                         const LinearSolverControls& solver)
    : controls_(controls), solver_controls_(solver) {}

TransientIntegrator::~TransientIntegrator() = default;

void TransientIntegrator::factor(const TransientSystem& s, double gamma) {
  if (factored_version_ == version_ && factored_gamma_ == gamma && solver_) return;
  SparseMatrix a = gamma * s.network.matrix;
  for (int i = 0; i < s.n(); ++i) a.coeffRef(i, i) += s.storage[i];
  if (!solver_ || analysed_n_ != s.n()) {
    solver_ = make_spd_solver(solver_controls_, s.n());
    analysed_n_ = s.n();
    solver_->analyze(a);
  }
  solver_->factorize(a);
  factored_version_ = version_;
  factored_gamma_ = gamma;
  ++factorizations_;
}

void TransientIntegrator::implicit_step(const TransientSystem& s, Eigen::VectorXd& x, double t1,
                                        double h) {
  Eigen::VectorXd r;
  s.rhs(t1, r);
  const bool bdf2 = controls_.scheme == Scheme::Bdf2 && history_version_ == version_ &&
                    previous_.size() == x.size() && previous_h_ > 0;
  Eigen::VectorXd b;
  double gamma = h;
  if (bdf2) {
    // a0 y1 - a1 y0 + a2 y_-1 = h f(y1), w = h / h_prev (core/base/bdf2.h).
    const Bdf2Coefficients a = bdf2_coefficients(h / previous_h_);
    gamma = h / a.a0;
    b = s.storage.cwiseProduct((a.a1 * x - a.a2 * previous_) / a.a0) + gamma * r;
  } else {
    b = s.storage.cwiseProduct(x) + h * r;
  }
  factor(s, gamma);
  previous_ = x;
  previous_h_ = h;
  history_version_ = version_;
  Eigen::VectorXd x1 = x;
  solver_->solve(b, x1);
  x = std::move(x1);
}

void TransientIntegrator::explicit_step(const TransientSystem& s, Eigen::VectorXd& x, double t0,
                                        double h) {
  Eigen::VectorXd r;
  s.rhs(t0, r);
  x += h * (r - s.network.matrix * x).cwiseQuotient(s.storage);
}

void TransientIntegrator::advance(const TransientSystem& s, Eigen::VectorXd& x, double t,
                                  double dt) {
  FISSURE_CHECK(x.size() == s.n(), SolverError, "flow: transient state does not match the network");
  explicit_limit_ = s.explicit_limit();
  if (s.n() == 0) return;
  if (controls_.scheme == Scheme::Cvode) {
    if (!cvode_) cvode_ = std::make_unique<CvodeIntegrator>(controls_, solver_controls_);
    cvode_->advance(s, x, t, dt, version_);
    return;
  }
  double h_max = controls_.time_step > 0 ? controls_.time_step : dt;
  if (controls_.scheme == Scheme::Explicit && controls_.time_step == 0)
    h_max = 0.9 * explicit_limit_;
  const long n_steps = std::max(1L, static_cast<long>(std::ceil(dt / h_max * (1 - 1e-12))));
  const double h = dt / static_cast<double>(n_steps);
  for (long k = 0; k < n_steps; ++k) {
    const double t0 = t + static_cast<double>(k) * h;
    if (controls_.scheme == Scheme::Explicit)
      explicit_step(s, x, t0, h);
    else
      implicit_step(s, x, t0 + h, h);
    ++steps_;
  }
  FISSURE_CHECK(x.allFinite(), DivergenceError,
                "flow: the transient pressures became non-finite at t = "
                    << t + dt << " s (explicit step " << h << " s against the explicit limit "
                    << explicit_limit_ << " s)");
}

nlohmann::json TransientIntegrator::statistics() const {
  static const char* names[] = {"cvode", "bdf2", "backward_euler", "explicit"};
  nlohmann::json j = {{"scheme", names[static_cast<int>(controls_.scheme)]},
                      {"explicit_limit", explicit_limit_}};
  if (cvode_) {
    j["cvode"] = cvode_->statistics();
  } else {
    j["steps"] = steps_;
    j["factorizations"] = factorizations_;
  }
  if (solver_) j["linear_solver"] = solver_->name();
  return j;
}

}  // namespace fissure::flow

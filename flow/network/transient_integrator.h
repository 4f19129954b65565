// Time integration of S dp*/dt + T p* = r(t) (transient_system.h), theory.md 3.4:
//  * backward_euler: (S + h T) x1 = S x0 + h r(t1); first order, L-stable;
//  * bdf2:           variable-step BDF2 (first step backward Euler);
//                    second order, L-stable;
//  * cvode:          SUNDIALS CVODE, variable-order variable-step BDF with
//                    Newton iterations; its linear systems (I - gamma J) are
//                    solved by GMRES preconditioned with the exact inverse
//                    (S + gamma T)^-1 S (a CHOLMOD factorization), so GMRES
//                    converges in one iteration;
//  * explicit:       forward Euler x1 = x0 + h S^-1 (r(t0) - T x0), UDEC's
//                    scheme; stable only for h <= min S_i / T_ii (the
//                    explicit limit, always reported), sharp on a chain.
// The implicit schemes are unconditionally stable: the flow step is not tied
// to the stiff explicit limit. Steps are at most `time_step` (sub-cycling);
// the explicit scheme with time_step 0 takes 0.9 x its limit.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "flow/network/flow_conditions.h"
#include "flow/network/spd_solver.h"
#include "flow/network/transient_system.h"

namespace fissure::flow {

class CvodeIntegrator;

class TransientIntegrator {
 public:
  TransientIntegrator(const TransientControls& controls, const LinearSolverControls& solver);
  ~TransientIntegrator();

  /// Advances the unknowns x (potentials p*) from t to t + dt. Call
  /// `network_changed()` first whenever the system was rebuilt.
  void advance(const TransientSystem& system, Eigen::VectorXd& x, double t, double dt);
  void network_changed() { version_++; }

  nlohmann::json statistics() const;
  double last_explicit_limit() const { return explicit_limit_; }

  /// The BDF2 history and the counters (core/io/checkpoint.h). CVODE starts
  /// afresh at every flow update (the system changes), so it keeps nothing
  /// across updates but its counters, which start again after a restart.
  template <class Self, class Archive>
  static void checkpoint(Self& self, Archive& a) {
    a("version", self.version_);
    a("previous", self.previous_);
    a("previous_h", self.previous_h_);
    a("history_version", self.history_version_);
    a("steps", self.steps_);
    a("factorizations", self.factorizations_);
    a("explicit_limit", self.explicit_limit_);
    if constexpr (Archive::reading) self.factored_version_ = -1;
  }

 private:
  void implicit_step(const TransientSystem& s, Eigen::VectorXd& x, double t1, double h);
  void explicit_step(const TransientSystem& s, Eigen::VectorXd& x, double t0, double h);
  void factor(const TransientSystem& s, double gamma);

  TransientControls controls_;
  LinearSolverControls solver_controls_;
  std::unique_ptr<SpdSolver> solver_;
  std::unique_ptr<CvodeIntegrator> cvode_;
  long version_ = 0, factored_version_ = -1;
  double factored_gamma_ = 0;
  int analysed_n_ = -1;
  // BDF2 history.
  Eigen::VectorXd previous_;
  double previous_h_ = 0;
  long history_version_ = -1;
  // Statistics.
  long steps_ = 0, factorizations_ = 0;
  double explicit_limit_ = 0;
};

}  // namespace fissure::flow

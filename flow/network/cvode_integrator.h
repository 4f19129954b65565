// SUNDIALS CVODE (BDF, orders 1-5, adaptive steps) for the transient network
// y' = S^-1 (r(t) - T y) (transient_system.h). Newton iterations with GMRES,
// an exact Jacobian-vector product and the exact preconditioner
// P^-1 = (S + gamma T)^-1 S (CHOLMOD), so that each linear solve takes one
// GMRES iteration; the step follows the error tolerances, not the stiff
// explicit limit. Every SUNDIALS call is checked (FISSURE_SUNDIALS_CALL).
#pragma once

#include <memory>
#include <nlohmann/json.hpp>

#include "flow/network/flow_conditions.h"
#include "flow/network/spd_solver.h"
#include "flow/network/transient_system.h"

namespace fissure::flow {

class CvodeIntegrator {
 public:
  CvodeIntegrator(const TransientControls& controls, const LinearSolverControls& solver);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// Integrates from t to t + dt. Continues the previous integration when the
  /// system (version) is unchanged and t is where it stopped; restarts
  /// (CVodeReInit, order 1) otherwise.
  void advance(const TransientSystem& system, Eigen::VectorXd& x, double t, double dt,
               long version);

  nlohmann::json statistics() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace fissure::flow

#include "flow/network/cvode_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_spgmr.h>

#include <cmath>
#include <string>

#include "core/base/errors.h"

// SUNDIALS convention: 0 success, > 0 recoverable, < 0 failure.
#define FISSURE_SUNDIALS_CALL(call)                                                               \
  do {                                                                                            \
    const int fissure_sundials_flag = (call);                                                     \
    FISSURE_CHECK(                                                                                \
        fissure_sundials_flag >= 0, ::fissure::SolverError,                                       \
        "SUNDIALS error " << fissure_sundials_flag << " in " #call << ": " << impl_->last_error); \
  } while (false)

namespace fissure::flow {

struct CvodeIntegrator::Impl {
  TransientControls controls;
  LinearSolverControls solver_controls;
  SUNContext context = nullptr;
  void* cvode = nullptr;
  N_Vector y = nullptr;
  SUNLinearSolver gmres = nullptr;
  int n = -1;
  long version = -1;
  double t_reached = NAN;
  const TransientSystem* system = nullptr;
  std::unique_ptr<SpdSolver> factor;
  double factored_gamma = NAN;
  long factored_version = -1, factorizations = 0;
  std::string last_error;
  Eigen::VectorXd work;
  /// Counters of earlier integrations (CVodeReInit and CVodeFree reset them).
  long totals[6] = {0, 0, 0, 0, 0, 0};

  void counters(long c[6]) const {
    c[0] = c[1] = c[2] = c[3] = c[4] = c[5] = 0;
    if (!cvode) return;
    CVodeGetNumSteps(cvode, &c[0]);
    CVodeGetNumRhsEvals(cvode, &c[1]);
    CVodeGetNumLinSolvSetups(cvode, &c[2]);
    CVodeGetNumErrTestFails(cvode, &c[3]);
    CVodeGetNumNonlinSolvIters(cvode, &c[4]);
    CVodeGetNumLinIters(cvode, &c[5]);
  }
  void bank_counters() {
    long c[6];
    counters(c);
    for (int k = 0; k < 6; ++k) totals[k] += c[k];
  }

  ~Impl() { release(); }
  void release() {
    bank_counters();
    if (cvode) CVodeFree(&cvode);
    if (gmres) SUNLinSolFree(gmres);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
    cvode = nullptr, gmres = nullptr, y = nullptr, context = nullptr;
  }

  static Eigen::Map<Eigen::VectorXd> map(N_Vector v) {
    return {N_VGetArrayPointer(v), static_cast<Eigen::Index>(N_VGetLength(v))};
  }

  // y' = S^-1 (r(t) - T y)
  static int rhs(double t, N_Vector y, N_Vector ydot, void* data) {
    auto* self = static_cast<Impl*>(data);
    const TransientSystem& s = *self->system;
    s.rhs(t, self->work);
    map(ydot) = (self->work - s.network.matrix * map(y)).cwiseQuotient(s.storage);
    return map(ydot).allFinite() ? 0 : 1;
  }

  // J v = -S^-1 T v (exact; the problem is linear in y).
  static int jtimes(N_Vector v, N_Vector jv, double, N_Vector, N_Vector, void* data, N_Vector) {
    auto* self = static_cast<Impl*>(data);
    const TransientSystem& s = *self->system;
    map(jv) = -(s.network.matrix * map(v)).cwiseQuotient(s.storage);
    return 0;
  }

  // P = I - gamma J = S^-1 (S + gamma T): factor S + gamma T.
  static int psetup(double, N_Vector, N_Vector, int, int* jcur, double gamma, void* data) {
    auto* self = static_cast<Impl*>(data);
    *jcur = 1;
    try {
      self->refactor(gamma);
    } catch (const std::exception& e) {
      self->last_error = e.what();
      return -1;
    }
    return 0;
  }

  // z = P^-1 r = (S + gamma T)^-1 S r.
  static int psolve(double, N_Vector, N_Vector, N_Vector r, N_Vector z, double, double, int,
                    void* data) {
    auto* self = static_cast<Impl*>(data);
    Eigen::VectorXd sol;
    self->factor->solve(self->system->storage.cwiseProduct(map(r)), sol);
    map(z) = sol;
    return 0;
  }

  static void on_error(int, const char* module, const char* function, char* msg, void* data) {
    static_cast<Impl*>(data)->last_error =
        std::string(module) + "." + function + ": " + (msg ? msg : "");
  }

  void refactor(double gamma) {
    if (factored_version == version && factored_gamma == gamma) return;
    SparseMatrix a = gamma * system->network.matrix;
    for (int i = 0; i < system->n(); ++i) a.coeffRef(i, i) += system->storage[i];
    if (!factor || factored_version < 0 || a.rows() != static_cast<long>(n)) {
      factor = make_spd_solver(solver_controls, system->n());
      factor->analyze(a);
    }
    factor->factorize(a);
    factored_gamma = gamma;
    factored_version = version;
    ++factorizations;
  }
};

CvodeIntegrator::CvodeIntegrator(const TransientControls& controls,
                                 const LinearSolverControls& solver)
    : impl_(std::make_unique<Impl>()) {
  impl_->controls = controls;
  impl_->solver_controls = solver;
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::advance(const TransientSystem& s, Eigen::VectorXd& x, double t, double dt,
                              long version) {
  Impl& m = *impl_;
  m.system = &s;
  const bool same_size = m.n == s.n() && m.cvode;
  const bool resume = same_size && version == m.version && t == m.t_reached;
  if (version != m.version) m.factored_version = -1;
  m.version = version;
  if (!same_size) {
    // (Re)create everything for a system of this size.
    m.release();
    m.n = s.n();
    FISSURE_SUNDIALS_CALL(SUNContext_Create(nullptr, &m.context));
    m.y = N_VNew_Serial(m.n, m.context);
    FISSURE_CHECK(m.y, SolverError, "SUNDIALS: could not allocate a vector of " << m.n);
    Impl::map(m.y) = x;
    m.cvode = CVodeCreate(CV_BDF, m.context);
    FISSURE_CHECK(m.cvode, SolverError, "SUNDIALS: CVodeCreate failed");
    FISSURE_SUNDIALS_CALL(CVodeSetErrHandlerFn(m.cvode, &Impl::on_error, &m));
    FISSURE_SUNDIALS_CALL(CVodeInit(m.cvode, &Impl::rhs, t, m.y));
    FISSURE_SUNDIALS_CALL(
        CVodeSStolerances(m.cvode, m.controls.relative_tolerance, m.controls.absolute_tolerance));
    FISSURE_SUNDIALS_CALL(CVodeSetUserData(m.cvode, &m));
    FISSURE_SUNDIALS_CALL(CVodeSetMaxNumSteps(m.cvode, 1000000));
    m.gmres = SUNLinSol_SPGMR(m.y, SUN_PREC_LEFT, 20, m.context);
    FISSURE_CHECK(m.gmres, SolverError, "SUNDIALS: SUNLinSol_SPGMR failed");
    FISSURE_SUNDIALS_CALL(CVodeSetLinearSolver(m.cvode, m.gmres, nullptr));
    FISSURE_SUNDIALS_CALL(CVodeSetJacTimes(m.cvode, nullptr, &Impl::jtimes));
    FISSURE_SUNDIALS_CALL(CVodeSetPreconditioner(m.cvode, &Impl::psetup, &Impl::psolve));
  } else if (!resume) {
    m.bank_counters();
    Impl::map(m.y) = x;
    FISSURE_SUNDIALS_CALL(CVodeReInit(m.cvode, t, m.y));
  }
  if (m.controls.time_step > 0)
    FISSURE_SUNDIALS_CALL(CVodeSetMaxStep(m.cvode, m.controls.time_step));
  // Never step past t + dt: the network or the conditions may change there.
  const double t_end = t + dt;
  FISSURE_SUNDIALS_CALL(CVodeSetStopTime(m.cvode, t_end));
  double t_reached = t;
  const int flag = CVode(m.cvode, t_end, m.y, &t_reached, CV_NORMAL);
  FISSURE_CHECK(
      flag >= 0, SolverError,
      "flow: CVODE failed at t = " << t_reached << " s (flag " << flag << "): " << m.last_error);
  m.t_reached = t_end;
  x = Impl::map(m.y);
}

nlohmann::json CvodeIntegrator::statistics() const {
  const Impl& m = *impl_;
  long c[6];
  m.counters(c);
  for (int k = 0; k < 6; ++k) c[k] += m.totals[k];
  int order = 0;
  if (m.cvode) CVodeGetLastOrder(m.cvode, &order);
  return {{"steps", c[0]},
          {"rhs_evaluations", c[1]},
          {"newton_iterations", c[4]},
          {"gmres_iterations", c[5]},
          {"preconditioner_setups", c[2]},
          {"factorizations", m.factorizations},
          {"error_test_failures", c[3]},
          {"last_order", order},
          {"relative_tolerance", m.controls.relative_tolerance},
          {"absolute_tolerance", m.controls.absolute_tolerance}};
}

}  // namespace fissure::flow

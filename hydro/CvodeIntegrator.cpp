#include "hydro/CvodeIntegrator.hpp"

#include <cvode/cvode.h>
#include <cvode/cvode_bandpre.h>
#include <cvode/cvode_ls.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_spgmr.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "hydro/SundialsKernels.hpp"

namespace granwave::hydro {

std::string cvodeFlagName(int flag) {
  const char* name = CVodeGetReturnFlagName(flag);
  std::string s = name ? name : "unknown";
  std::free(const_cast<char*>(name));  // CVODE allocates the name
  // SUNDIALS 6.4's lookup does not know every code it returns.
  if (s == "NONE" && flag == CV_CONSTR_FAIL) s = "CV_CONSTR_FAIL";
  return s;
}

struct CvodeIntegrator::Impl {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, abstol = nullptr, constraints = nullptr;
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* cvode = nullptr;
  RightHandSide f;
  BandJacobian jacobian;
  std::function<void(double, const double*, double*)> event_functions;
  std::function<void(double, std::vector<double>&, const std::vector<int>&)> on_event;
  int events = 0;
  long max_events = 0, handled = 0;
  // The counters of the integrations before the last restart (CVodeReInit zeroes CVODE's).
  CvodeStats carried;
  KrylovPreconditioner preconditioner;
  ComponentName name;
  std::vector<double> out;
  double t = 0;
  int n = 0;
  std::string rhs_error;  // an exception escaping the RHS, reported after CVODE returns
  // Right-hand sides refused as not finite (flag > 0: CVODE retries with a shorter step) since
  // the last output time, and the first component that was not, in the state or else in its
  // rate, of the last one refused (a refused state leaves the rates unwritten).
  long refused = 0;
  int refused_component = -1;
  bool refused_state = false;

  ~Impl() {
    if (cvode) CVodeFree(&cvode);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (constraints) N_VDestroy(constraints);
    if (abstol) N_VDestroy(abstol);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }

  static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      const int flag = self->f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
      if (flag > 0) self->noteRefused(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
      return flag;
    } catch (const std::exception& e) {
      self->rhs_error = e.what();
      return -1;
    }
  }

  static int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->event_functions(t, N_VGetArrayPointer(y), g);
      return 0;
    } catch (const std::exception& e) {
      self->rhs_error = e.what();
      return -1;
    }
  }

  // Handles the event CVODE stopped at and restarts the integration from its state.
  void handleEvent(double t_root) {
    std::vector<int> found(static_cast<std::size_t>(events), 0);
    check(CVodeGetRootInfo(cvode, found.data()), "CVodeGetRootInfo");
    double* yp = N_VGetArrayPointer(y);
    std::copy(yp, yp + n, out.begin());
    on_event(t_root, out, found);
    std::copy(out.begin(), out.end(), yp);
    carried = current();
    check(CVodeReInit(cvode, t_root, y), "CVodeReInit");
    ++handled;
  }

  // The counters since the start: those carried over restarts plus CVODE's own. (After a
  // restart CVODE zeroes its linear solver's counters only when the next CVode call starts;
  // no counter is read in between.)
  CvodeStats current() const;

  static int jac(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector,
                 N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      return self->jacobian(t, N_VGetArrayPointer(y),
                            [J](int row, int col, double v) { SM_ELEMENT_B(J, row, col) = v; });
    } catch (const std::exception& e) {
      self->rhs_error = e.what();
      return -1;
    }
  }

  static int psetup(sunrealtype t, N_Vector y, N_Vector, sunbooleantype jok, sunbooleantype* jcur,
                    sunrealtype gamma, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      bool recomputed = false;
      const int flag =
          self->preconditioner.setup(t, N_VGetArrayPointer(y), jok == SUNTRUE, gamma, recomputed);
      *jcur = recomputed ? SUNTRUE : SUNFALSE;
      return flag;
    } catch (const std::exception& e) {
      self->rhs_error = e.what();
      return -1;
    }
  }

  static int psolve(sunrealtype, N_Vector, N_Vector, N_Vector r, N_Vector z, sunrealtype,
                    sunrealtype, int, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      return self->preconditioner.solve(N_VGetArrayPointer(r), N_VGetArrayPointer(z));
    } catch (const std::exception& e) {
      self->rhs_error = e.what();
      return -1;
    }
  }

  void noteRefused(const double* y, const double* yd) {
    ++refused;
    refused_component = -1;
    for (int k = 0; k < n && refused_component < 0; ++k)
      if (!std::isfinite(y[k])) refused_component = k;
    refused_state = refused_component >= 0;
    for (int k = 0; k < n && refused_component < 0; ++k)
      if (!std::isfinite(yd[k])) refused_component = k;
  }

  // The component with the largest weighted local error estimate, -1 if unavailable or if
  // every estimate is zero (after failed Newton iterations CVODE has none to give).
  int worstComponent() const {
    N_Vector ele = N_VClone(y), w = N_VClone(y);
    int worst = -1;
    if (CVodeGetEstLocalErrors(cvode, ele) == CV_SUCCESS &&
        CVodeGetErrWeights(cvode, w) == CV_SUCCESS) {
      const double* e = N_VGetArrayPointer(ele);
      const double* wt = N_VGetArrayPointer(w);
      double best = 0;
      for (int i = 0; i < n; ++i) {
        const double v = std::abs(e[i] * wt[i]);
        if (std::isfinite(v) && v > best) {
          best = v;
          worst = i;
        }
      }
    }
    N_VDestroy(ele);
    N_VDestroy(w);
    return worst;
  }

  [[noreturn]] void fail(const char* call, int flag) const {
    double h = 0, tcur = t;
    if (cvode) {
      CVodeGetLastStep(cvode, &h);
      CVodeGetCurrentTime(cvode, &tcur);
    }
    const int worst = cvode ? worstComponent() : -1;
    std::ostringstream msg;
    msg << call << " failed: " << cvodeFlagName(flag) << " (" << flag << ") at t = " << tcur
        << " s, last step " << h << " s";
    if (worst >= 0)
      msg << ", largest local error in "
          << (name ? name(worst) : "component " + std::to_string(worst));
    if (!rhs_error.empty()) msg << "; right-hand side: " << rhs_error;
    if (refused > 0 && refused_component >= 0)
      msg << "; " << refused
          << " right-hand side(s) not finite since the last output, the last in the "
          << (refused_state ? "state" : "rate") << " of "
          << (name ? name(refused_component) : "component " + std::to_string(refused_component));
    throw CvodeError(msg.str(), call, flag, tcur, h, worst);
  }

  void check(int flag, const char* call) const {
    if (flag < 0) fail(call, flag);
  }

  // The linear (BDF) or fixed-point (Adams) solver of o.method, with its Jacobian or
  // preconditioner.
  void attachSolver(const CvodeOptions& o);
};

namespace {
extern "C" void silentErrorHandler(int, const char*, const char*, char*, void*) {}
}  // namespace

void CvodeIntegrator::Impl::attachSolver(const CvodeOptions& o) {
  Impl& m = *this;
  switch (o.method) {
    case CvodeMethod::BdfBanded:
      m.A = SUNBandMatrix(m.n, o.band_upper, o.band_lower, m.ctx);
      if (!m.A) m.fail("SUNBandMatrix", -20);
      useCompiledKernels(m.A);
      m.LS = bandLuSolver(m.A, m.ctx);
      if (!m.LS) m.fail("bandLuSolver", -20);
      m.check(CVodeSetLinearSolver(m.cvode, m.LS, m.A), "CVodeSetLinearSolver");
      if (o.jacobian) {
        m.jacobian = o.jacobian;
        m.check(CVodeSetJacFn(m.cvode, Impl::jac), "CVodeSetJacFn");
      }
      if (o.jacobian_frequency > 0)
        m.check(CVodeSetJacEvalFrequency(m.cvode, o.jacobian_frequency),
                "CVodeSetJacEvalFrequency");
      break;
    case CvodeMethod::BdfKrylov:
      m.LS = SUNLinSol_SPGMR(m.y, SUN_PREC_LEFT, o.krylov_dimension, m.ctx);
      if (!m.LS) m.fail("SUNLinSol_SPGMR", -20);
      m.check(CVodeSetLinearSolver(m.cvode, m.LS, nullptr), "CVodeSetLinearSolver");
      if (o.preconditioner.solve) {
        m.preconditioner = o.preconditioner;
        m.check(CVodeSetPreconditioner(m.cvode, Impl::psetup, Impl::psolve),
                "CVodeSetPreconditioner");
      } else {
        m.check(CVBandPrecInit(m.cvode, m.n, o.band_upper, o.band_lower), "CVBandPrecInit");
      }
      if (o.linear_tolerance_factor > 0)
        m.check(CVodeSetEpsLin(m.cvode, o.linear_tolerance_factor), "CVodeSetEpsLin");
      if (o.jacobian_frequency > 0)
        m.check(CVodeSetJacEvalFrequency(m.cvode, o.jacobian_frequency),
                "CVodeSetJacEvalFrequency");
      break;
    case CvodeMethod::Adams:
      m.NLS = SUNNonlinSol_FixedPoint(m.y, 0, m.ctx);
      if (!m.NLS) m.fail("SUNNonlinSol_FixedPoint", -20);
      m.check(CVodeSetNonlinearSolver(m.cvode, m.NLS), "CVodeSetNonlinearSolver");
      break;
  }
}

CvodeIntegrator::CvodeIntegrator(RightHandSide f, double t0, const std::vector<double>& y0,
                                 const CvodeOptions& o, ComponentName name)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.f = std::move(f);
  m.name = std::move(name);
  m.n = static_cast<int>(y0.size());
  m.t = t0;
  if (m.n == 0) throw std::invalid_argument("CVODE needs a non-empty state");
  if (!(o.rtol > 0) || o.atol.size() != y0.size())
    throw std::invalid_argument(
        "CVODE tolerances: rtol must be > 0 and atol must have one entry per component");
  for (double a : o.atol)
    if (!(a > 0)) throw std::invalid_argument("CVODE tolerances: every atol must be > 0");
  m.check(SUNContext_Create(nullptr, &m.ctx), "SUNContext_Create");
  m.y = N_VNew_Serial(m.n, m.ctx);
  m.abstol = N_VNew_Serial(m.n, m.ctx);
  if (!m.y || !m.abstol) m.fail("N_VNew_Serial", -20);
  useCompiledKernels(m.y);  // CVODE's work vectors are clones of y: they inherit the kernels
  useCompiledKernels(m.abstol);
  std::copy(y0.begin(), y0.end(), N_VGetArrayPointer(m.y));
  std::copy(o.atol.begin(), o.atol.end(), N_VGetArrayPointer(m.abstol));

  m.cvode = CVodeCreate(o.method == CvodeMethod::Adams ? CV_ADAMS : CV_BDF, m.ctx);
  if (!m.cvode) m.fail("CVodeCreate", -20);
  CVodeSetErrHandlerFn(m.cvode, silentErrorHandler, nullptr);  // we report errors ourselves
  m.check(CVodeInit(m.cvode, Impl::rhs, t0, m.y), "CVodeInit");
  m.check(CVodeSetUserData(m.cvode, &m), "CVodeSetUserData");
  m.check(CVodeSVtolerances(m.cvode, o.rtol, m.abstol), "CVodeSVtolerances");
  m.check(CVodeSetMaxNumSteps(m.cvode, o.max_steps), "CVodeSetMaxNumSteps");
  if (o.max_step > 0) m.check(CVodeSetMaxStep(m.cvode, o.max_step), "CVodeSetMaxStep");
  if (o.max_order > 0) m.check(CVodeSetMaxOrd(m.cvode, o.max_order), "CVodeSetMaxOrd");
  m.attachSolver(o);
  if (o.method != CvodeMethod::Adams && o.stability_limit_detection)
    m.check(CVodeSetStabLimDet(m.cvode, SUNTRUE), "CVodeSetStabLimDet");
  if (!o.constraints.empty()) {
    if (o.constraints.size() != y0.size())
      throw std::invalid_argument("CVODE constraints: one entry per component");
    m.constraints = N_VNew_Serial(m.n, m.ctx);
    if (!m.constraints) m.fail("N_VNew_Serial", -20);
    useCompiledKernels(m.constraints);
    std::copy(o.constraints.begin(), o.constraints.end(), N_VGetArrayPointer(m.constraints));
    m.check(CVodeSetConstraints(m.cvode, m.constraints), "CVodeSetConstraints");
  }
  if (o.events > 0) {
    if (!o.event_functions || !o.on_event)
      throw std::invalid_argument("CVODE events: event_functions and on_event are both needed");
    m.events = o.events;
    m.event_functions = o.event_functions;
    m.on_event = o.on_event;
    m.max_events = o.max_events;
    m.check(CVodeRootInit(m.cvode, o.events, Impl::roots), "CVodeRootInit");
  }
  m.out.assign(y0.begin(), y0.end());
}

CvodeIntegrator::~CvodeIntegrator() = default;
CvodeIntegrator::CvodeIntegrator(CvodeIntegrator&&) noexcept = default;
CvodeIntegrator& CvodeIntegrator::operator=(CvodeIntegrator&&) noexcept = default;

void CvodeIntegrator::advanceTo(double tout) {
  Impl& m = *impl_;
  m.rhs_error.clear();
  m.refused = 0;
  m.refused_component = -1;
  sunrealtype t = m.t;
  long events = 0;
  for (;;) {
    const int flag = CVode(m.cvode, tout, m.y, &t, CV_NORMAL);
    if (flag < 0) m.fail("CVode", flag);
    m.t = t;
    if (flag != CV_ROOT_RETURN) break;
    if (++events > m.max_events)
      throw CvodeError("more than " + std::to_string(m.max_events) +
                           " events before t = " + std::to_string(tout) +
                           " s (the last at t = " + std::to_string(t) + " s): an event chatters",
                       "CVode", CV_ROOT_RETURN, t, m.current().last_step, -1);
    m.handleEvent(t);
    if (t >= tout) break;  // a root at tout: its restart is the output, nothing left to do
  }
  const double* y = N_VGetArrayPointer(m.y);
  std::copy(y, y + m.n, m.out.begin());
}

double CvodeIntegrator::time() const { return impl_->t; }
const std::vector<double>& CvodeIntegrator::state() const { return impl_->out; }

int CvodeIntegrator::largestErrorComponent() const { return impl_->worstComponent(); }

CvodeStats CvodeIntegrator::stats() const { return impl_->current(); }

CvodeStats CvodeIntegrator::Impl::current() const {
  const Impl& m = *this;
  CvodeStats s;
  CVodeGetNumSteps(m.cvode, &s.steps);
  CVodeGetNumRhsEvals(m.cvode, &s.rhs_evals);
  CVodeGetNumErrTestFails(m.cvode, &s.err_test_fails);
  CVodeGetNumNonlinSolvConvFails(m.cvode, &s.nonlin_conv_fails);
  CVodeGetNumNonlinSolvIters(m.cvode, &s.nonlin_iters);
  CVodeGetLastStep(m.cvode, &s.last_step);
  CVodeGetLastOrder(m.cvode, &s.last_order);
  if (m.LS) {
    CVodeGetNumLinRhsEvals(m.cvode, &s.lin_rhs_evals);
    CVodeGetNumJacEvals(m.cvode, &s.jac_evals);
    CVodeGetNumLinIters(m.cvode, &s.lin_iters);
    CVodeGetNumLinConvFails(m.cvode, &s.lin_conv_fails);
    CVodeGetNumPrecEvals(m.cvode, &s.prec_evals);
    CVodeGetNumPrecSolves(m.cvode, &s.prec_solves);
  }
  const CvodeStats& c = m.carried;
  s.steps += c.steps;
  s.rhs_evals += c.rhs_evals;
  s.lin_rhs_evals += c.lin_rhs_evals;
  s.jac_evals += c.jac_evals;
  s.err_test_fails += c.err_test_fails;
  s.nonlin_conv_fails += c.nonlin_conv_fails;
  s.nonlin_iters += c.nonlin_iters;
  s.lin_iters += c.lin_iters;
  s.lin_conv_fails += c.lin_conv_fails;
  s.prec_evals += c.prec_evals;
  s.prec_solves += c.prec_solves;
  s.events = m.handled;
  return s;
}

}  // namespace granwave::hydro

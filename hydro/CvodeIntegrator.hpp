#pragma once
// One move-only owner of every SUNDIALS object (context, vectors, matrix, linear solver,
// CVODE memory): SUNDIALS changed its API in 6 and 7, so no SUNDIALS type appears in this
// header (style.md, item 7). Every failing call becomes a CvodeError naming the call, the
// return code, t, the last step size and the state component with the largest weighted
// local error (where the solution went bad).
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace granwave::hydro {

// Writes one element of a banded matrix: (row, column, value).
using BandMatrixWriter = std::function<void(int row, int column, double value)>;
// Fills the Jacobian d(dy/dt)/dy at (t, y) through the writer; 0 = success, > 0 recoverable.
using BandJacobian = std::function<int(double t, const double* y, const BandMatrixWriter& write)>;

enum class CvodeMethod {
  BdfBanded,  // BDF, Newton, banded direct solver (the caller's Jacobian, else difference
              // quotients)
  BdfKrylov,  // BDF, Newton-Krylov (GMRES) with a band preconditioner, or the caller's
              // (CvodeOptions::preconditioner)
  Adams,      // Adams-Moulton, functional (fixed-point) iteration: non-stiff reference
};

// A left preconditioner P ~ I - gamma J of the caller's for BdfKrylov (CVODE's psetup and
// psolve). setup(t, y, jacobian_ok, gamma) prepares P, reusing its saved Jacobian when
// jacobian_ok allows, and returns whether it evaluated a new one in `recomputed`; solve(r, z)
// sets z = P^-1 r. Both return 0, > 0 for a recoverable failure, < 0 for an unrecoverable one.
struct KrylovPreconditioner {
  std::function<int(double t, const double* y, bool jacobian_ok, double gamma, bool& recomputed)>
      setup;
  std::function<int(const double* r, double* z)> solve;
};

struct CvodeOptions {
  CvodeMethod method = CvodeMethod::BdfBanded;
  double rtol = 1e-6;
  std::vector<double> atol;               // one per component
  int max_order = 0;                      // 0 = method default (BDF 5, Adams 12)
  bool stability_limit_detection = true;  // BDF only (CVodeSetStabLimDet)
  double max_step = 0;                    // s, 0 = no limit
  long max_steps = 20'000;  // per CVode call: an output interval, or its part between events
  int band_upper = 0, band_lower = 0;
  std::vector<double> constraints;  // empty = none; else per component 0, 1, 2 (CVODE semantics)
  BandJacobian jacobian;            // BdfBanded: exact Jacobian; empty = difference quotients
  int jacobian_frequency = 0;       // max steps between Jacobian evaluations (0 = CVODE's 51)
  KrylovPreconditioner preconditioner;  // BdfKrylov: empty = CVODE's band preconditioner
  int krylov_dimension = 0;             // BdfKrylov: GMRES's largest subspace (0 = 5)
  double linear_tolerance_factor = 0;   // BdfKrylov: CVodeSetEpsLin (0 = CVODE's 0.05)
  // Events (CVODE's root finding): `events` functions g_k(t, y) written by event_functions,
  // located where one changes sign. At a root on_event(t, y, found) (found[k] != 0 for each
  // g_k that crossed) may change y and whatever the right-hand side reads besides y; the
  // integration then restarts from (t, y) (CVodeReInit: no step's history crosses a jump).
  int events = 0;
  std::function<void(double t, const double* y, double* g)> event_functions;
  std::function<void(double t, std::vector<double>& y, const std::vector<int>& found)> on_event;
  long max_events = 1000;  // per advanceTo(): more is a chattering event, an error (terminal)
};

struct CvodeStats {
  long steps = 0, rhs_evals = 0, lin_rhs_evals = 0, jac_evals = 0;
  long err_test_fails = 0, nonlin_conv_fails = 0, nonlin_iters = 0;
  long lin_iters = 0, lin_conv_fails = 0, prec_evals = 0, prec_solves = 0;  // Krylov
  long events = 0;  // events handled (CvodeOptions::events)
  double last_step = 0;
  int last_order = 0;
};

class CvodeError : public std::runtime_error {
 public:
  CvodeError(const std::string& what, std::string call, int flag, double t, double h, int worst)
      : std::runtime_error(what),
        call_(std::move(call)),
        flag_(flag),
        t_(t),
        h_(h),
        worst_(worst) {}
  const std::string& call() const { return call_; }
  int flag() const { return flag_; }
  double time() const { return t_; }
  double lastStep() const { return h_; }
  int worstComponent() const { return worst_; }

 private:
  std::string call_;
  int flag_;
  double t_, h_;
  int worst_;
};

// dy/dt = f(t, y). Return 0 on success, > 0 for a recoverable failure (CVODE retries with a
// smaller step), < 0 for an unrecoverable one.
using RightHandSide = std::function<int(double t, const double* y, double* ydot)>;
// Names a state component in error messages ("cell 12 (z' = 1.3 mm), temperature").
using ComponentName = std::function<std::string(int component)>;

class CvodeIntegrator {
 public:
  CvodeIntegrator(RightHandSide f, double t0, const std::vector<double>& y0,
                  const CvodeOptions& options, ComponentName name = {});
  ~CvodeIntegrator();
  CvodeIntegrator(CvodeIntegrator&&) noexcept;
  CvodeIntegrator& operator=(CvodeIntegrator&&) noexcept;
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  // Integrates to tout (normal mode: interpolated output at tout), handling the events met
  // on the way. Throws CvodeError; after one the integrator cannot go on.
  void advanceTo(double tout);
  double time() const;
  const std::vector<double>& state() const;
  CvodeStats stats() const;
  // The component with the largest weighted local error estimate of the last step (-1 if
  // unavailable or every estimate is zero): where the integrator spends its steps.
  int largestErrorComponent() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Human-readable name of a CVODE return code ("CV_CONV_FAILURE").
std::string cvodeFlagName(int flag);

}  // namespace granwave::hydro

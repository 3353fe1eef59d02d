#include "sim/time/sundials_plugin.hpp"
#include "sim/time/external_stepper.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <ida/ida.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>


namespace mmv {

/// Errors inside the plugin (never leaves it: the stepper turns it into a string).
struct PluginFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace {

using Method = SundialsIntegrator::Method;

/// The smallest step CVODE Adams may take (s); see its use.
constexpr double kMinStepS = 1e-12;

bool isArkode(Method m) { return m == Method::ArkErk || m == Method::ArkDirk; }

std::string flagName(Method m, int flag) {
  char* name = m == Method::ArkErk ? ERKStepGetReturnFlagName(flag)
               : m == Method::ArkDirk ? ARKStepGetReturnFlagName(flag)
               : m == Method::Ida     ? IDAGetReturnFlagName(flag)
                                      : CVodeGetReturnFlagName(flag);
  std::string s = name ? name : "unknown flag";
  std::free(name);  // SUNDIALS allocates it
  return s;
}

const char* packageName(Method m) { return isArkode(m) ? "ARKODE" : m == Method::Ida ? "IDA" : "CVODE"; }

void check(Method m, int flag, const char* call) {
  if (flag < 0) throw PluginFailure(std::string(packageName(m)) + " " + call + " failed: " + flagName(m, flag));
}

template <class T, void (*Free)(T)>
struct Handle {
  T p = nullptr;
  ~Handle() {
    if (p) Free(p);
  }
};
void freeVector(N_Vector v) { N_VDestroy(v); }
void freeMatrix(SUNMatrix m) { SUNMatDestroy(m); }
void freeLinearSolver(SUNLinearSolver s) { SUNLinSolFree(s); }
void freeNonlinearSolver(SUNNonlinearSolver s) { SUNNonlinSolFree(s); }

}  // namespace

struct Context {
  SUNContext c = nullptr;
  Context() {
    if (SUNContext_Create(nullptr, &c) != 0) throw PluginFailure("SUNContext_Create failed");
  }
  ~Context() {
    if (c) SUNContext_Free(&c);
  }
};
struct Memory {
  Method method = Method::Bdf;
  void* p = nullptr;
  ~Memory() {
    if (!p) return;
    if (method == Method::ArkErk) ERKStepFree(&p);
    else if (method == Method::ArkDirk) ARKStepFree(&p);
    else if (method == Method::Ida) IDAFree(&p);
    else CVodeFree(&p);
  }
};

// Members are destroyed in reverse order of declaration: the CVODE memory first, then
// the solvers and vectors it used, the SUNDIALS context last.
struct SundialsIntegrator::Impl {
  const SimTK::MultibodySystem& system;
  Method method;
  double rtol, atol;
  Context ctx;
  Handle<N_Vector, freeVector> y;
  Handle<N_Vector, freeVector> yp, id;  // IDA: y', and which components are differential
  int ny = 0, np = 0;                   // IDA: Simbody's state size, position constraints
  Handle<SUNMatrix, freeMatrix> A;
  Handle<SUNLinearSolver, freeLinearSolver> ls;
  Handle<SUNNonlinearSolver, freeNonlinearSolver> nls;
  Memory mem;
  SimTK::State work;
  double seconds = 0;  // inside the solver's calls
  double end_time = 0;  // the run's end (sizes the first step)
  double reached = 0;   // the solver's internal time
  const ReducedCoordinates* reduced = nullptr;  // y is theirs when given
  std::vector<double> reduced_ydot, reduced_jacobian;
  // SUNDIALS' own account of its last error, and what the right-hand side threw: they go
  // into the failure's message instead of stderr (its default printer wrote
  // "[ARKODE ERROR] ..." in the middle of a command's output, for a failure the command
  // reports anyway, or one a contract's pilot expects and moves past).
  std::string solver_said, rhs_threw;
  Impl(const SimTK::MultibodySystem& s, Method m, double r, double a, const ReducedCoordinates* rc)
      : system(s), method(m), rtol(r), atol(a), reduced(rc) {}

  /// Copies y into `work`, applies the prescribed motions and realizes to Acceleration
  /// (reduced coordinates: `full` as ReducedCoordinates::load).
  void load(double t, N_Vector yv, bool full = true) {
    if (reduced) {
      reduced->load(t, N_VGetArrayPointer(yv), work, reduced_ydot.data(), full);
      return;
    }
    work.setTime(t);
    SimTK::Vector& Y = work.updY();
    const double* d = N_VGetArrayPointer(yv);
    for (int i = 0; i < Y.size(); ++i) Y[i] = d[i];
    system.realize(work, SimTK::Stage::Time);
    system.prescribeQ(work);
    system.realize(work, SimTK::Stage::Position);
    system.prescribeU(work);
    system.realize(work, SimTK::Stage::Acceleration);
  }

  /// SUNDIALS' error and warning handler (same signature in CVODE, ARKODE and IDA).
  static void sundialsSaid(int code, const char* module, const char* function, char* msg, void* user) {
    if (code < 0) static_cast<Impl*>(user)->solver_said = std::string(module) + " " + function + ": " + msg;
  }

  /// Inside a callback's catch: keeps what was thrown, returns SUNDIALS' "unrecoverable".
  int threw() {
    try {
      throw;
    } catch (const std::exception& e) {
      rhs_threw = e.what();
    } catch (...) {
      rhs_threw = "an exception of unknown type";
    }
    return -1;
  }

  /// Why the solver stopped, in its words: " (MODULE Function: message; the right-hand
  /// side threw: ...)", or "" when it said nothing.
  std::string why() const {
    std::string s = solver_said;
    if (!rhs_threw.empty()) s += (s.empty() ? "" : "; ") + std::string("the right-hand side threw: ") + rhs_threw;
    return s.empty() ? s : " (" + s + ")";
  }

  /// IDA: F = [q' - qdot - ~Pq mu; u' - udot; perr] over y = [q; u; mu].
  static int residual(double t, N_Vector yv, N_Vector ypv, N_Vector rr, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->load(t, yv);
      const SimTK::State& w = self->work;
      const double* y = N_VGetArrayPointer(yv);
      const double* yp = N_VGetArrayPointer(ypv);
      double* r = N_VGetArrayPointer(rr);
      const SimTK::Vector& yd = w.getYDot();
      const int nq = w.getNQ(), n = self->ny, np = self->np;
      SimTK::Vector correction(nq, 0.0);
      if (np > 0) {
        SimTK::Vector mu(np);
        for (int i = 0; i < np; ++i) mu[i] = y[n + i];
        self->system.getMatterSubsystem().multiplyByPqTranspose(w, mu, correction);
      }
      for (int i = 0; i < n; ++i) {
        r[i] = yp[i] - yd[i] - (i < nq ? correction[i] : 0.0);
        if (!std::isfinite(r[i])) return 1;
      }
      for (int i = 0; i < np; ++i) r[n + i] = w.getQErr()[i];
      return 0;
    } catch (...) {
      return self->threw();
    }
  }

  /// The reduced coordinates' own Jacobian (ReducedCoordinates::jacobian).
  static int jacobian(double t, N_Vector yv, N_Vector, SUNMatrix J, void* user, N_Vector, N_Vector, N_Vector) {
    auto* self = static_cast<Impl*>(user);
    try {
      const int n = static_cast<int>(self->reduced_ydot.size());
      self->reduced_jacobian.resize(static_cast<std::size_t>(n) * n);
      if (!self->reduced->jacobian(t, N_VGetArrayPointer(yv), self->reduced_jacobian.data())) return -1;
      for (int j = 0; j < n; ++j) {
        double* col = SUNDenseMatrix_Column(J, j);
        for (int i = 0; i < n; ++i) col[i] = self->reduced_jacobian[static_cast<std::size_t>(j) * n + i];
      }
      return 0;
    } catch (...) {
      return self->threw();
    }
  }

  static int rhs(double t, N_Vector yv, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->load(t, yv, false);
      double* out = N_VGetArrayPointer(ydot);
      if (self->reduced) {
        for (std::size_t i = 0; i < self->reduced_ydot.size(); ++i) {
          if (!std::isfinite(self->reduced_ydot[i])) return 1;
          out[i] = self->reduced_ydot[i];
        }
        return 0;
      }
      const SimTK::Vector& yd = self->work.getYDot();
      for (int i = 0; i < yd.size(); ++i) {
        if (!std::isfinite(yd[i])) return 1;  // recoverable: CVODE retries with a smaller step
        out[i] = yd[i];
      }
      return 0;
    } catch (...) {
      return self->threw();  // unrecoverable
    }
  }
};

SundialsIntegrator::SundialsIntegrator(const SimTK::MultibodySystem& system, Method method, double rtol, double atol,
                                       const ReducedCoordinates* reduced)
    : impl_(std::make_unique<Impl>(system, method, rtol, atol > 0 ? atol : rtol, reduced)) {}

SundialsIntegrator::~SundialsIntegrator() = default;

void SundialsIntegrator::initialize(const SimTK::State& s) {
  Impl& m = *impl_;
  const Method me = m.method;
  m.work = s;
  m.reached = s.getTime();
  if (me == Method::Ida) {
    if (m.reduced) throw PluginFailure("IDA integrates Simbody's own coordinates only: reduced (modal) links need an ODE method (cvode_bdf, cvode_adams, arkode_erk, arkode_dirk)");
    initializeIda(s);
    return;
  }
  const int n = m.reduced ? m.reduced->size() : s.getNY();
  m.y.p = N_VNew_Serial(n, m.ctx.c);
  if (!m.y.p) throw PluginFailure("SUNDIALS: cannot allocate the state vector");
  double* d = N_VGetArrayPointer(m.y.p);
  if (m.reduced) {
    m.reduced_ydot.assign(n, 0.0);
    m.reduced->project(s, d);
  } else {
    for (int i = 0; i < n; ++i) d[i] = s.getY()[i];
  }
  m.mem.method = me;
  // Absolute tolerance: given, or the relative one times a unit scale (rad, m, rad/s, m/s).
  switch (me) {
    case Method::Adams:
    case Method::Bdf:
      m.mem.p = CVodeCreate(me == Method::Bdf ? CV_BDF : CV_ADAMS, m.ctx.c);
      if (!m.mem.p) throw PluginFailure("CVodeCreate failed");
      check(me, CVodeSetErrHandlerFn(m.mem.p, &Impl::sundialsSaid, &m), "CVodeSetErrHandlerFn");
      check(me, CVodeInit(m.mem.p, &Impl::rhs, s.getTime(), m.y.p), "CVodeInit");
      check(me, CVodeSetUserData(m.mem.p, &m), "CVodeSetUserData");
      check(me, CVodeSStolerances(m.mem.p, m.rtol, m.atol), "CVodeSStolerances");
      check(me, CVodeSetMaxNumSteps(m.mem.p, 1000000), "CVodeSetMaxNumSteps");
      // Adams' fixed-point iteration takes a failed right-hand side for a convergence
      // failure and retries at a smaller step, without end when the minimum step is 0
      // (SUNDIALS' default): a model that throws hung the run. 1e-12 s is far below
      // any step a multibody run takes; under it CVODE stops with CV_CONV_FAILURE.
      if (me == Method::Adams) check(me, CVodeSetMinStep(m.mem.p, kMinStepS), "CVodeSetMinStep");
      break;
    case Method::ArkErk:
      m.mem.p = ERKStepCreate(&Impl::rhs, s.getTime(), m.y.p, m.ctx.c);
      if (!m.mem.p) throw PluginFailure("ERKStepCreate failed");
      check(me, ERKStepSetErrHandlerFn(m.mem.p, &Impl::sundialsSaid, &m), "ERKStepSetErrHandlerFn");
      check(me, ERKStepSetUserData(m.mem.p, &m), "ERKStepSetUserData");
      check(me, ERKStepSStolerances(m.mem.p, m.rtol, m.atol), "ERKStepSStolerances");
      check(me, ERKStepSetMaxNumSteps(m.mem.p, 1000000), "ERKStepSetMaxNumSteps");
      break;
    case Method::ArkDirk:
      m.mem.p = ARKStepCreate(nullptr, &Impl::rhs, s.getTime(), m.y.p, m.ctx.c);  // all implicit
      if (!m.mem.p) throw PluginFailure("ARKStepCreate failed");
      check(me, ARKStepSetErrHandlerFn(m.mem.p, &Impl::sundialsSaid, &m), "ARKStepSetErrHandlerFn");
      check(me, ARKStepSetUserData(m.mem.p, &m), "ARKStepSetUserData");
      check(me, ARKStepSStolerances(m.mem.p, m.rtol, m.atol), "ARKStepSStolerances");
      check(me, ARKStepSetMaxNumSteps(m.mem.p, 1000000), "ARKStepSetMaxNumSteps");
      break;
  }
  if (me == Method::Bdf || me == Method::ArkDirk) {
    m.A.p = SUNDenseMatrix(n, n, m.ctx.c);
    m.ls.p = SUNLinSol_Dense(m.y.p, m.A.p, m.ctx.c);
    if (!m.A.p || !m.ls.p) throw PluginFailure("SUNDIALS: cannot create the dense linear solver for " + std::to_string(n) + " states");
    if (me == Method::Bdf) check(me, CVodeSetLinearSolver(m.mem.p, m.ls.p, m.A.p), "CVodeSetLinearSolver");
    else check(me, ARKStepSetLinearSolver(m.mem.p, m.ls.p, m.A.p), "ARKStepSetLinearSolver");
    std::vector<double> probe(static_cast<std::size_t>(n) * n);
    if (m.reduced && m.reduced->jacobian(s.getTime(), d, probe.data())) {
      if (me == Method::Bdf) check(me, CVodeSetJacFn(m.mem.p, &Impl::jacobian), "CVodeSetJacFn");
      else check(me, ARKStepSetJacFn(m.mem.p, &Impl::jacobian), "ARKStepSetJacFn");
    }
  } else if (me == Method::Adams) {
    m.nls.p = SUNNonlinSol_FixedPoint(m.y.p, 0, m.ctx.c);
    if (!m.nls.p) throw PluginFailure("CVODE: cannot create the fixed-point solver");
    check(me, CVodeSetNonlinearSolver(m.mem.p, m.nls.p), "CVodeSetNonlinearSolver");
  }
  m.load(s.getTime(), m.y.p);
}

void SundialsIntegrator::initializeIda(const SimTK::State& s) {
  Impl& m = *impl_;
  const Method me = Method::Ida;
  m.system.realize(m.work, SimTK::Stage::Acceleration);
  if (s.getNQ() != s.getNU())
    throw PluginFailure("IDA here needs as many q as u (free bodies with quaternions are not supported): use cvode_bdf");
  m.ny = s.getNY();
  m.np = s.getNQErr();
  const int n = m.ny + m.np;
  m.y.p = N_VNew_Serial(n, m.ctx.c);
  m.yp.p = N_VNew_Serial(n, m.ctx.c);
  m.id.p = N_VNew_Serial(n, m.ctx.c);
  if (!m.y.p || !m.yp.p || !m.id.p) throw PluginFailure("SUNDIALS: cannot allocate IDA's vectors");
  double* y = N_VGetArrayPointer(m.y.p);
  double* yp = N_VGetArrayPointer(m.yp.p);
  double* id = N_VGetArrayPointer(m.id.p);
  // Consistent start: the state (on its closures), its derivative, multipliers 0.
  for (int i = 0; i < m.ny; ++i) y[i] = s.getY()[i], yp[i] = m.work.getYDot()[i], id[i] = 1.0;
  for (int i = m.ny; i < n; ++i) y[i] = 0.0, yp[i] = 0.0, id[i] = 0.0;
  m.mem.method = me;
  m.mem.p = IDACreate(m.ctx.c);
  if (!m.mem.p) throw PluginFailure("IDACreate failed");
  check(me, IDASetErrHandlerFn(m.mem.p, &Impl::sundialsSaid, &m), "IDASetErrHandlerFn");
  check(me, IDAInit(m.mem.p, &Impl::residual, s.getTime(), m.y.p, m.yp.p), "IDAInit");
  check(me, IDASetUserData(m.mem.p, &m), "IDASetUserData");
  check(me, IDASStolerances(m.mem.p, m.rtol, m.atol), "IDASStolerances");
  check(me, IDASetMaxNumSteps(m.mem.p, 1000000), "IDASetMaxNumSteps");
  check(me, IDASetId(m.mem.p, m.id.p), "IDASetId");
  check(me, IDASetSuppressAlg(m.mem.p, SUNTRUE), "IDASetSuppressAlg");  // multipliers: index 2
  // An index-2 iteration matrix's conditioning grows as 1/h^2: IDA's own first step
  // (from |y'| and the tolerances, about 1e-8 s here) makes it singular in double, so
  // start at a step a multibody run resolves anyway.
  if (m.np > 0) check(me, IDASetInitStep(m.mem.p, 1e-4), "IDASetInitStep");
  m.A.p = SUNDenseMatrix(n, n, m.ctx.c);
  m.ls.p = SUNLinSol_Dense(m.y.p, m.A.p, m.ctx.c);
  if (!m.A.p || !m.ls.p) throw PluginFailure("SUNDIALS: cannot create IDA's dense linear solver for " + std::to_string(n) + " unknowns");
  check(me, IDASetLinearSolver(m.mem.p, m.ls.p, m.A.p), "IDASetLinearSolver");
  m.load(s.getTime(), m.y.p);
}

void SundialsIntegrator::stepTo(double t) {
  Impl& m = *impl_;
  const Method me = m.method;
  void* mem = m.mem.p;
  const auto start = std::chrono::steady_clock::now();
  // One internal step at a time until the integrator has passed t, then its dense output
  // at t: the steps do not depend on the sample times (CV_NORMAL's first step would
  // follow the first sample's distance). tout, the run's end, only sizes the first step.
  const double tout = std::max(m.end_time, t);
  double reached = m.reached;
  while (reached < t) {
    const int flag = me == Method::ArkErk    ? ERKStepEvolve(mem, tout, m.y.p, &reached, ARK_ONE_STEP)
                     : me == Method::ArkDirk ? ARKStepEvolve(mem, tout, m.y.p, &reached, ARK_ONE_STEP)
                     : me == Method::Ida     ? IDASolve(mem, tout, &reached, m.y.p, m.yp.p, IDA_ONE_STEP)
                                             : CVode(mem, tout, m.y.p, &reached, CV_ONE_STEP);
    if (flag < 0)
      throw PluginFailure(std::string(packageName(me)) + " stopped at t = " + std::to_string(reached) +
                          " s: " + flagName(me, flag) + m.why());
  }
  m.reached = reached;
  const int flag = me == Method::ArkErk    ? ERKStepGetDky(mem, t, 0, m.y.p)
                   : me == Method::ArkDirk ? ARKStepGetDky(mem, t, 0, m.y.p)
                   : me == Method::Ida     ? IDAGetDky(mem, t, 0, m.y.p)
                                           : CVodeGetDky(mem, t, 0, m.y.p);
  check(me, flag, "GetDky");
  m.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  m.load(t, m.y.p);
}

void SundialsIntegrator::setEndTime(double t) { impl_->end_time = t; }

const SimTK::State& SundialsIntegrator::getState() const { return impl_->work; }

IntegratorStats SundialsIntegrator::stats() const {
  void* mem = impl_->mem.p;
  IntegratorStats st;
  long err = 0, conv = 0, fe = 0, fi = 0, lin = 0;
  // The dense Newton solvers' difference-quotient Jacobians cost evaluations too.
  switch (impl_->method) {
    case Method::ArkErk:
      ERKStepGetNumSteps(mem, &st.steps);
      ERKStepGetNumErrTestFails(mem, &err);
      ERKStepGetNumRhsEvals(mem, &fe);
      break;
    case Method::ArkDirk:
      ARKStepGetNumSteps(mem, &st.steps);
      ARKStepGetNumErrTestFails(mem, &err);
      ARKStepGetNumNonlinSolvConvFails(mem, &conv);
      ARKStepGetNumRhsEvals(mem, &fe, &fi);
      ARKStepGetNumLinRhsEvals(mem, &lin);
      ARKStepGetNumJacEvals(mem, &st.jacobians);
      break;
    case Method::Ida:
      IDAGetNumSteps(mem, &st.steps);
      IDAGetNumErrTestFails(mem, &err);
      IDAGetNumNonlinSolvConvFails(mem, &conv);
      IDAGetNumResEvals(mem, &fi);
      IDAGetNumLinResEvals(mem, &lin);
      IDAGetNumJacEvals(mem, &st.jacobians);
      break;
    case Method::Bdf:
      CVodeGetNumLinRhsEvals(mem, &lin);
      CVodeGetNumJacEvals(mem, &st.jacobians);
      [[fallthrough]];
    case Method::Adams:
      CVodeGetNumSteps(mem, &st.steps);
      CVodeGetNumErrTestFails(mem, &err);
      CVodeGetNumNonlinSolvConvFails(mem, &conv);
      CVodeGetNumRhsEvals(mem, &fi);
      break;
  }
  st.seconds = impl_->seconds;
  st.rejected = err + conv;
  st.evaluations = fe + fi + lin;
  return st;
}

}  // namespace mmv

namespace mmv {
namespace {

class CvodeStepper : public ExternalStepper {
 public:
  CvodeStepper(const SimTK::MultibodySystem& sys, SundialsIntegrator::Method method, double rtol, double atol,
               const ReducedCoordinates* reduced)
      : integ_(sys, method, rtol, atol, reduced) {}
  bool initialize(const SimTK::State& s, std::string& error) override { return guard([&] { integ_.initialize(s); }, error); }
  bool stepTo(double t, std::string& error) override { return guard([&] { integ_.stepTo(t); }, error); }
  void setEndTime(double t) override { integ_.setEndTime(t); }
  const SimTK::State& state() const override { return integ_.getState(); }
  IntegratorStats stats() const override { return integ_.stats(); }

 private:
  template <class F>
  static bool guard(F&& f, std::string& error) {
    try {
      f();
      return true;
    } catch (const std::exception& e) {
      error = e.what();
      return false;
    }
  }
  SundialsIntegrator integ_;
};

}  // namespace
}  // namespace mmv

extern "C" __attribute__((visibility("default"))) mmv::ExternalStepper* mmv_create_sundials_stepper_v2(
    const SimTK::MultibodySystem* system, int method, double rtol, double atol, const mmv::ReducedCoordinates* reduced) {
  if (method < 0 || method > 4) return nullptr;
  return new mmv::CvodeStepper(*system, static_cast<mmv::SundialsIntegrator::Method>(method), rtol, atol, reduced);
}

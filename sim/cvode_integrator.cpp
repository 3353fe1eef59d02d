#include "sim/cvode_integrator.hpp"
#include "sim/external_stepper.hpp"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <string>


namespace mmv {

/// Errors inside the plugin (never leaves it: the stepper turns it into a string).
struct NumericalError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace {

void check(int flag, const char* call) {
  if (flag < 0) throw NumericalError(std::string("CVODE ") + call + " failed: " + CVodeGetReturnFlagName(flag));
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
    if (SUNContext_Create(nullptr, &c) != 0) throw NumericalError("SUNContext_Create failed");
  }
  ~Context() {
    if (c) SUNContext_Free(&c);
  }
};
struct Memory {
  void* p = nullptr;
  ~Memory() {
    if (p) CVodeFree(&p);
  }
};

// Members are destroyed in reverse order of declaration: the CVODE memory first, then
// the solvers and vectors it used, the SUNDIALS context last.
struct CvodeIntegrator::Impl {
  const SimTK::MultibodySystem& system;
  Method method;
  double rtol;
  Context ctx;
  Handle<N_Vector, freeVector> y;
  Handle<SUNMatrix, freeMatrix> A;
  Handle<SUNLinearSolver, freeLinearSolver> ls;
  Handle<SUNNonlinearSolver, freeNonlinearSolver> nls;
  Memory mem;
  SimTK::State work;
  Impl(const SimTK::MultibodySystem& s, Method m, double r) : system(s), method(m), rtol(r) {}

  /// Copies y into `work`, applies the prescribed motions and realizes to Acceleration.
  void load(double t, N_Vector yv) {
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

  static int rhs(double t, N_Vector yv, N_Vector ydot, void* user) {
    auto* self = static_cast<Impl*>(user);
    try {
      self->load(t, yv);
      const SimTK::Vector& yd = self->work.getYDot();
      double* out = N_VGetArrayPointer(ydot);
      for (int i = 0; i < yd.size(); ++i) {
        if (!std::isfinite(yd[i])) return 1;  // recoverable: CVODE retries with a smaller step
        out[i] = yd[i];
      }
      return 0;
    } catch (...) {
      return -1;  // unrecoverable
    }
  }
};

CvodeIntegrator::CvodeIntegrator(const SimTK::MultibodySystem& system, Method method, double rtol)
    : impl_(std::make_unique<Impl>(system, method, rtol)) {}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::initialize(const SimTK::State& s) {
  Impl& m = *impl_;
  m.work = s;
  const int n = s.getNY();
  m.y.p = N_VNew_Serial(n, m.ctx.c);
  if (!m.y.p) throw NumericalError("CVODE: cannot allocate the state vector");
  double* d = N_VGetArrayPointer(m.y.p);
  for (int i = 0; i < n; ++i) d[i] = s.getY()[i];
  m.mem.p = CVodeCreate(m.method == Method::Bdf ? CV_BDF : CV_ADAMS, m.ctx.c);
  if (!m.mem.p) throw NumericalError("CVodeCreate failed");
  check(CVodeInit(m.mem.p, &Impl::rhs, s.getTime(), m.y.p), "CVodeInit");
  check(CVodeSetUserData(m.mem.p, &m), "CVodeSetUserData");
  // Absolute tolerance: the relative one times a unit scale (rad, m, rad/s, m/s).
  check(CVodeSStolerances(m.mem.p, m.rtol, m.rtol), "CVodeSStolerances");
  check(CVodeSetMaxNumSteps(m.mem.p, 1000000), "CVodeSetMaxNumSteps");
  if (m.method == Method::Bdf) {
    m.A.p = SUNDenseMatrix(n, n, m.ctx.c);
    m.ls.p = SUNLinSol_Dense(m.y.p, m.A.p, m.ctx.c);
    if (!m.A.p || !m.ls.p)
      throw NumericalError("CVODE: cannot create the dense linear solver (vector id " +
                           std::to_string(N_VGetVectorID(m.y.p)) + ", length " + std::to_string(N_VGetLength(m.y.p)) +
                           ", matrix " + (m.A.p ? std::to_string(SUNMatGetID(m.A.p)) + " " +
                                                      std::to_string(SUNDenseMatrix_Rows(m.A.p)) + "x" +
                                                      std::to_string(SUNDenseMatrix_Columns(m.A.p))
                                                : std::string("null")) + ")");
    check(CVodeSetLinearSolver(m.mem.p, m.ls.p, m.A.p), "CVodeSetLinearSolver");
  } else {
    m.nls.p = SUNNonlinSol_FixedPoint(m.y.p, 0, m.ctx.c);
    if (!m.nls.p) throw NumericalError("CVODE: cannot create the fixed-point solver");
    check(CVodeSetNonlinearSolver(m.mem.p, m.nls.p), "CVodeSetNonlinearSolver");
  }
  m.load(s.getTime(), m.y.p);
  state_ = m.work;
}

void CvodeIntegrator::stepTo(double t) {
  Impl& m = *impl_;
  double reached = 0;
  const int flag = CVode(m.mem.p, t, m.y.p, &reached, CV_NORMAL);
  if (flag < 0)
    throw NumericalError(std::string("CVODE stopped at t = ") + std::to_string(reached) + " s: " +
                         CVodeGetReturnFlagName(flag));
  m.load(reached, m.y.p);
  state_ = m.work;
  m.system.realize(state_, SimTK::Stage::Acceleration);
}

long CvodeIntegrator::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->mem.p, &n);
  return n;
}

long CvodeIntegrator::rhsEvaluations() const {
  long n = 0, jac = 0;
  CVodeGetNumRhsEvals(impl_->mem.p, &n);
  // The dense Newton solver's difference-quotient Jacobians cost evaluations too.
  if (impl_->method == Method::Bdf) CVodeGetNumLinRhsEvals(impl_->mem.p, &jac);
  return n + jac;
}

}  // namespace mmv

namespace mmv {
namespace {

class CvodeStepper : public ExternalStepper {
 public:
  CvodeStepper(const SimTK::MultibodySystem& sys, bool bdf, double rtol)
      : integ_(sys, bdf ? CvodeIntegrator::Method::Bdf : CvodeIntegrator::Method::Adams, rtol) {}
  bool initialize(const SimTK::State& s, std::string& error) override { return guard([&] { integ_.initialize(s); }, error); }
  bool stepTo(double t, std::string& error) override { return guard([&] { integ_.stepTo(t); }, error); }
  const SimTK::State& state() const override { return integ_.getState(); }
  long steps() const override { return integ_.steps(); }
  long evaluations() const override { return integ_.rhsEvaluations(); }

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
  CvodeIntegrator integ_;
};

}  // namespace
}  // namespace mmv

extern "C" mmv::ExternalStepper* mmv_create_cvode_stepper(const SimTK::MultibodySystem* system, int bdf, double rtol) {
  return new mmv::CvodeStepper(*system, bdf != 0, rtol);
}

#include "sim/time/run_integrator.hpp"

#include <algorithm>
#include <chrono>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

/// Simbody's integrator for `id`; nullptr for SUNDIALS' (sundialsMethod). Every id is
/// named in one of the two switches (no default: a new id unhandled is a warning).
std::unique_ptr<SimTK::Integrator> makeSimbodyIntegrator(IntegratorId id, const SimTK::MultibodySystem& sys) {
  switch (id) {
    case IntegratorId::RkMerson: return std::make_unique<SimTK::RungeKuttaMersonIntegrator>(sys);
    case IntegratorId::RkFeldberg: return std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(sys);
    case IntegratorId::Rk3: return std::make_unique<SimTK::RungeKutta3Integrator>(sys);
    case IntegratorId::Rk2: return std::make_unique<SimTK::RungeKutta2Integrator>(sys);
    case IntegratorId::CPodes:
      return std::make_unique<SimTK::CPodesIntegrator>(sys, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    case IntegratorId::Verlet: return std::make_unique<SimTK::VerletIntegrator>(sys);
    case IntegratorId::SemiExplicitEuler2: return std::make_unique<SimTK::SemiExplicitEuler2Integrator>(sys);
    case IntegratorId::ExplicitEuler: return std::make_unique<SimTK::ExplicitEulerIntegrator>(sys);
    case IntegratorId::CvodeBdf:
    case IntegratorId::CvodeAdams:
    case IntegratorId::ArkodeErk:
    case IntegratorId::ArkodeDirk:
    case IntegratorId::Ida: return nullptr;
  }
  return nullptr;
}

SundialsMethod sundialsMethod(IntegratorId id) {
  switch (id) {
    case IntegratorId::CvodeBdf: return SundialsMethod::CvodeBdf;
    case IntegratorId::CvodeAdams: return SundialsMethod::CvodeAdams;
    case IntegratorId::ArkodeErk: return SundialsMethod::ArkodeErk;
    case IntegratorId::ArkodeDirk: return SundialsMethod::ArkodeDirk;
    case IntegratorId::Ida: return SundialsMethod::Ida;
    case IntegratorId::RkMerson:
    case IntegratorId::RkFeldberg:
    case IntegratorId::Rk3:
    case IntegratorId::Rk2:
    case IntegratorId::CPodes:
    case IntegratorId::Verlet:
    case IntegratorId::SemiExplicitEuler2:
    case IntegratorId::ExplicitEuler: break;
  }
  throw InternalError("integrator id without a SUNDIALS method");
}

}  // namespace

RunIntegrator::RunIntegrator(const SimTK::MultibodySystem& sys, const std::string& name, double accuracy,
                             const SimTK::State& initial, const std::string& source, double atol,
                             const ReducedCoordinates* reduced)
    : system_(sys), name_(name), accuracy_(accuracy) {
  // Checked where the user gave them (the scene reader, the studies, trade's options):
  // Simbody asserts (and aborts) outside (0, 1).
  MMV_DEMAND(accuracy > 0 && accuracy < 1);
  const IntegratorInfo& info = integratorInfo(name);
  if (reduced && !info.runs_modal_links)
    throw SceneError(source + ": links in modal coordinates (links[].modes) run under SUNDIALS' ODE methods "
                     "(cvode_bdf, cvode_adams, arkode_erk, arkode_dirk), not " + name);
  if (info.family == IntegratorInfo::Family::Sundials) {
    MMV_DEMAND(atol >= 0 && atol < 1);
    sundials_ = makeSundialsStepper(sys, sundialsMethod(info.id), accuracy, atol, reduced);
    std::string error;
    if (!sundials_->initialize(initial, error)) throw NumericalError(error);
    return;
  }
  MMV_DEMAND(atol == 0);  // an absolute tolerance is SUNDIALS' only (checked with the integrator)
  integ_ = makeSimbodyIntegrator(info.id, sys);
  integ_->setAccuracy(accuracy);
  integ_->setInternalStepLimit(1000000);
  // One internal step per call, never shortened to hit a sample: the samples are
  // interpolated here (interpolateTo), into one work state, where Simbody's own
  // interpolation copies the whole state (cache included) at every sample.
  integ_->setReturnEveryInternalStep(true);
  integ_->setAllowInterpolation(false);
  try {
    integ_->initialize(initial);
    work_ = integ_->getState();
    system_.realize(work_, SimTK::Stage::Acceleration);
  } catch (const std::exception& e) {
    // Simbody's own words (e.g. a mass matrix singular to working precision: bodies whose
    // inertias differ by 20 decades, a 1e10 m table beside 0.5 kg pendulums): a numerical
    // failure of this model, exit 1, not an internal error.
    std::string why = e.what();
    std::replace(why.begin(), why.end(), '\n', ' ');
    throw NumericalError("the " + name_ + " integrator could not start: the model's equations cannot be solved at t = " +
                         std::to_string(initial.getTime()) + " s (" + why + ")");
  }
  t1_ = work_.getTime();
  y1_ = work_.getY();
  yd1_ = work_.getYDot();
}

RunIntegrator::~RunIntegrator() = default;

void RunIntegrator::stepTo(double t) {
  if (sundials_) {
    std::string error;  // names the SUNDIALS flag
    if (!sundials_->stepTo(t, error)) throw NumericalError(error);
    return;
  }
  const double tol = 1e-12 * std::max(1.0, std::abs(t));
  const auto start = std::chrono::steady_clock::now();
  try {
    // Internal steps until one ends at or past t (the end of the run limits the last).
    // The first call after initialize() returns the start of the interval.
    while (t1_ < t - tol) {
      const auto status = integ_->stepTo(std::max(end_time_, t), SimTK::Infinity);
      if (status == SimTK::Integrator::EndOfSimulation) break;
      if (status == SimTK::Integrator::StartOfContinuousInterval) continue;
      t0_ = t1_, y0_ = y1_, yd0_ = yd1_;
      const SimTK::State& a = integ_->getState();
      system_.realize(a, SimTK::Stage::Acceleration);
      t1_ = a.getTime(), y1_ = a.getY(), yd1_ = a.getYDot();
    }
  } catch (const NumericalError&) {
    throw;
  } catch (const std::exception& e) {
    throw NumericalError("integration failed at t = " + std::to_string(integ_->getTime()) + " s: " + e.what());
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (t1_ < t - 1e-9 * std::max(1.0, std::abs(t)))
    throw NumericalError("the " + name_ + " integrator stopped at t = " + std::to_string(t1_) +
                         " s: " + SimTK::Integrator::getTerminationReasonString(integ_->getTerminationReason()));
  interpolateTo(std::min(t, t1_));
}

void RunIntegrator::setEndTime(double t) {
  end_time_ = t;
  if (sundials_) sundials_->setEndTime(t);
}

void RunIntegrator::interpolateTo(double t) {
  // Cubic Hermite on the last step, from its end values and derivatives (as Simbody's own
  // interpolation), then the prescribed motions and, with closures, the projection onto
  // them to the integrator's accuracy.
  SimTK::Vector& y = work_.updY();
  const double h = t1_ - t0_;
  if (!(h > 0) || t >= t1_) {
    y = y1_;
  } else {
    const double s = (t - t0_) / h, s2 = s * s, s3 = s2 * s;
    const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
    for (int i = 0; i < y.size(); ++i) y[i] = h00 * y0_[i] + h10 * h * yd0_[i] + h01 * y1_[i] + h11 * h * yd1_[i];
  }
  work_.setTime(t);
  if (work_.getNQErr() > 0 || work_.getNUErr() > 0) {
    system_.project(work_, accuracy_);
  } else {
    system_.realize(work_, SimTK::Stage::Time);
    system_.prescribeQ(work_);
    system_.realize(work_, SimTK::Stage::Position);
    system_.prescribeU(work_);
  }
  system_.realize(work_, SimTK::Stage::Acceleration);
}

const SimTK::State& RunIntegrator::state() const { return sundials_ ? sundials_->state() : work_; }

IntegratorStats RunIntegrator::stats() const {
  if (sundials_) return sundials_->stats();
  IntegratorStats st;
  st.steps = integ_->getNumStepsTaken();
  st.seconds = seconds_;
  st.rejected = integ_->getNumErrorTestFailures() + integ_->getNumConvergenceTestFailures();
  st.evaluations = integ_->getNumRealizations();
  // The explicit methods form no Jacobian; CPodes (Newton) does but Simbody does not
  // report how often: -1, printed as such.
  if (name_ == "cpodes") st.jacobians = -1;
  return st;
}

}  // namespace mmv

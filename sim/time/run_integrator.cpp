#include "sim/time/run_integrator.hpp"

#include <map>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

std::unique_ptr<SimTK::Integrator> makeIntegrator(const std::string& name, const SimTK::MultibodySystem& sys,
                                                  const std::string& source) {
  if (name == "rk_merson") return std::make_unique<SimTK::RungeKuttaMersonIntegrator>(sys);
  if (name == "rk_feldberg") return std::make_unique<SimTK::RungeKuttaFeldbergIntegrator>(sys);
  if (name == "rk3") return std::make_unique<SimTK::RungeKutta3Integrator>(sys);
  if (name == "rk2") return std::make_unique<SimTK::RungeKutta2Integrator>(sys);
  if (name == "cpodes") return std::make_unique<SimTK::CPodesIntegrator>(sys, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
  if (name == "verlet") return std::make_unique<SimTK::VerletIntegrator>(sys);
  if (name == "semi_explicit_euler2") return std::make_unique<SimTK::SemiExplicitEuler2Integrator>(sys);
  if (name == "explicit_euler") return std::make_unique<SimTK::ExplicitEulerIntegrator>(sys);
  throw SceneError(source + ": unknown integrator '" + name + "'" + integratorSuggestion(name) + " (known: " +
                   integratorNames() + ")");
}

}  // namespace

RunIntegrator::RunIntegrator(const SimTK::MultibodySystem& sys, const std::string& name, double accuracy,
                             const SimTK::State& initial, const std::string& source, double atol)
    : name_(name), accuracy_(accuracy) {
  // Simbody asserts (and aborts) outside (0, 1); say so instead.
  if (!(accuracy > 0 && accuracy < 1))
    throw SceneError(source + ": simulation accuracy must be in (0, 1) (got " + std::to_string(accuracy) + ")");
  static const std::map<std::string, SundialsMethod> kSundials{{"cvode_bdf", SundialsMethod::CvodeBdf},
                                                               {"cvode_adams", SundialsMethod::CvodeAdams},
                                                               {"arkode_erk", SundialsMethod::ArkodeErk},
                                                               {"arkode_dirk", SundialsMethod::ArkodeDirk},
                                                               {"ida", SundialsMethod::Ida}};
  if (const auto it = kSundials.find(name); it != kSundials.end()) {
    if (!(atol >= 0 && atol < 1))
      throw SceneError(source + ": simulation absolute tolerance must be in [0, 1) (got " + std::to_string(atol) + ")");
    sundials_ = makeSundialsStepper(sys, it->second, accuracy, atol);
    std::string error;
    if (!sundials_->initialize(initial, error)) throw NumericalError(error);
    return;
  }
  if (atol > 0)
    throw SceneError(source + ": an absolute tolerance applies to the SUNDIALS integrators; " + name + " measures its error relative to the state's unit scale only");
  integ_ = makeIntegrator(name, sys, source);
  integ_->setAccuracy(accuracy);
  integ_->setInternalStepLimit(1000000);
  integ_->setReturnEveryInternalStep(false);
  stepper_ = std::make_unique<SimTK::TimeStepper>(sys, *integ_);
  stepper_->initialize(initial);
}

RunIntegrator::~RunIntegrator() = default;

void RunIntegrator::stepTo(double t) {
  if (sundials_) {
    std::string error;  // names the SUNDIALS flag
    if (!sundials_->stepTo(t, error)) throw NumericalError(error);
    return;
  }
  try {
    stepper_->stepTo(t);
  } catch (const NumericalError&) {
    throw;
  } catch (const std::exception& e) {
    throw NumericalError("integration failed at t = " + std::to_string(integ_->getTime()) + " s: " + e.what());
  }
  if (integ_->isSimulationOver() && integ_->getTime() < t - 1e-9 * std::max(1.0, std::abs(t)))
    throw NumericalError("the " + name_ + " integrator stopped at t = " + std::to_string(integ_->getTime()) +
                         " s: " + SimTK::Integrator::getTerminationReasonString(integ_->getTerminationReason()));
}

const SimTK::State& RunIntegrator::state() const { return sundials_ ? sundials_->state() : integ_->getState(); }

int RunIntegrator::steps() const {
  return sundials_ ? static_cast<int>(sundials_->steps()) : integ_->getNumStepsTaken();
}

int RunIntegrator::evaluations() const {
  return sundials_ ? static_cast<int>(sundials_->evaluations()) : integ_->getNumRealizations();
}

}  // namespace mmv

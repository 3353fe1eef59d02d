#pragma once
/// One integrator for a time run, by name: Simbody's through a TimeStepper, or
/// SUNDIALS' through the plugin (sim/time/external_stepper.hpp). Shared by every time run
/// (the article's and the isolator's) so integrators are chosen, checked and reported
/// the same way.

#include <Simbody.h>

#include <memory>
#include <string>

#include "sim/core/integrators.hpp"
#include "sim/time/external_stepper.hpp"

namespace mmv {

class RunIntegrator {
 public:
  /// Names come from sim/core/integrators.hpp. Throws SceneError (`source` in the message) for an unknown name or an accuracy
  /// outside (0, 1), NumericalError if SUNDIALS cannot start.
  /// `absolute_tolerance` > 0 applies to SUNDIALS' methods (SceneError for Simbody's,
  /// which measure errors on the state's unit scale only); 0: the accuracy.
  RunIntegrator(const SimTK::MultibodySystem& system, const std::string& name, double accuracy,
                const SimTK::State& initial, const std::string& source, double absolute_tolerance = 0);
  ~RunIntegrator();
  /// Advances to t; throws NumericalError naming the integrator's reason and the time.
  void stepTo(double t);
  const SimTK::State& state() const;
  int steps() const;
  int evaluations() const;  ///< realizations (Simbody) or right-hand-side evaluations (SUNDIALS).

 private:
  std::string name_;
  double accuracy_;
  std::unique_ptr<SimTK::Integrator> integ_;
  std::unique_ptr<SimTK::TimeStepper> stepper_;
  std::unique_ptr<ExternalStepper> sundials_;
};

}  // namespace mmv

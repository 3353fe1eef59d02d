#pragma once
/// One integrator for a time run, by name: Simbody's, stepped directly, or SUNDIALS'
/// through the plugin (sim/time/external_stepper.hpp). Both take the steps their error
/// control chooses and interpolate the state at each sample time (Simbody's cubic
/// Hermite, SUNDIALS' dense output), so the sample rate costs only the sampling: a
/// TimeStepper would pass every report time as a scheduled event, which stops the
/// integrator there (steps = samples). Shared by every time run
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
  /// `reduced`: the run integrates those coordinates (links in modal coordinates,
  /// sim/time/modal_links.hpp; kept by the caller): SUNDIALS' ODE methods only, any other
  /// name is a SceneError.
  RunIntegrator(const SimTK::MultibodySystem& system, const std::string& name, double accuracy,
                const SimTK::State& initial, const std::string& source, double absolute_tolerance = 0,
                const ReducedCoordinates* reduced = nullptr);
  ~RunIntegrator();
  /// Where the run ends (call before the first stepTo): Simbody's integrators do not
  /// step past it, SUNDIALS' size their first step by it (and may step past the end
  /// by one step, interpolating back). Default: no end; the first sample time for SUNDIALS.
  void setEndTime(double t);
  /// Advances to t; throws NumericalError naming the integrator's reason and the time.
  void stepTo(double t);
  /// The state at the last stepTo (or the start), realized to Acceleration; valid until the next stepTo.
  const SimTK::State& state() const;
  /// What the run cost the integrator (SUNDIALS' counters, or Simbody's equivalents).
  IntegratorStats stats() const;

 private:
  void interpolateTo(double t);

  const SimTK::MultibodySystem& system_;
  std::string name_;
  double accuracy_;
  double end_time_ = SimTK::Infinity;
  double seconds_ = 0;  ///< inside Simbody's steps
  // Simbody: the last internal step [t0, t1] with its end states and derivatives, and
  // the state handed out (interpolated in it).
  double t0_ = 0, t1_ = 0;
  SimTK::Vector y0_, yd0_, y1_, yd1_;
  SimTK::State work_;
  std::unique_ptr<SimTK::Integrator> integ_;
  std::unique_ptr<ExternalStepper> sundials_;
};

}  // namespace mmv

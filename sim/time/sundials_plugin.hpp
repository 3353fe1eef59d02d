#pragma once
/// SUNDIALS CVODE, ARKODE or IDA on a Simbody system: y = Simbody's Y (q, u, z), y' = f(t, y) from
/// realizing a State to Acceleration after applying the prescribed motions (slews, the
/// table), built into the plugin libmmvlab_sundials.so. CVODE: BDF with a dense Newton solver (stiff models) or Adams with
/// fixed-point iteration (non-stiff). ARKODE: ERKStep's default adaptive explicit
/// Runge-Kutta (order 4, non-stiff) or ARKStep fully implicit (its default order-4
/// SDIRK, dense Newton; stiff). Every SUNDIALS object is owned by an RAII handle and every
/// return code is checked: a failure throws NumericalError naming the CVODE flag
/// (CV_TOO_MUCH_WORK: too many steps; CV_ERR_FAILURE / CV_CONV_FAILURE: the step size
/// underflowed on error-test or convergence failures; ...) and the time.

#include <memory>
#include <string>

#include <Simbody.h>

#include "sim/time/external_stepper.hpp"

namespace mmv {

class SundialsIntegrator {
 public:
  /// The plugin's method codes. Ida: the equations as a DAE, F(t, y, y') = 0, with the
  /// position constraints (closures) held as algebraic equations by stabilizing
  /// multipliers (Gear-Gupta-Leimkuhler): q' = qdot(q, u) + ~Pq mu, u' = udot(q, u),
  /// perr(q) = 0; the multipliers are left out of the error test (index 2).
  enum class Method { Adams = 0, Bdf = 1, ArkErk = 2, ArkDirk = 3, Ida = 4 };
  /// absolute_tolerance <= 0: the relative one.
  /// `reduced`: integrate those coordinates instead of Simbody's Y (not IDA; kept by the caller).
  SundialsIntegrator(const SimTK::MultibodySystem& system, Method method, double relative_tolerance,
                  double absolute_tolerance = 0, const ReducedCoordinates* reduced = nullptr);
  ~SundialsIntegrator();
  SundialsIntegrator(const SundialsIntegrator&) = delete;
  SundialsIntegrator& operator=(const SundialsIntegrator&) = delete;

  void initialize(const SimTK::State& s);
  /// Advances to time t (> the current time) by the integrator's own steps and its dense
  /// output; the state is then realized to Acceleration.
  void stepTo(double t);
  /// The state at the last stepTo (or the start): the integrator's work state, valid
  /// until the next stepTo (copying it at every sample cost more than realizing it).
  const SimTK::State& getState() const;
  /// The run's end: sizes the first step (call before the first stepTo).
  void setEndTime(double t);
  IntegratorStats stats() const;

 private:
  void initializeIda(const SimTK::State& s);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mmv

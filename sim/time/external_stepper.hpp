#pragma once
/// An integrator that lives outside the main program: SUNDIALS (CVODE, ARKODE, IDA) is loaded from a
/// plugin (libmmvlab_sundials.so) with dlopen(RTLD_LOCAL), because Debian's libSimTKmath
/// exports its own, older copy of SUNDIALS' N_Vector and CVODE symbols (for Simbody's
/// CPodes): linked into one program the two interpose on each other and crash. The
/// plugin carries SUNDIALS 6 from its static archives with every symbol hidden
/// (--exclude-libs, -Bsymbolic), so its calls bind inside it; it exports only its
/// factory. (It used RTLD_DEEPBIND before, which AddressSanitizer's runtime refuses.)
/// Errors cross the boundary as strings, not exceptions.

#include <Simbody.h>

#include <memory>
#include <string>

namespace mmv {

/// What a run cost its integrator.
struct IntegratorStats {
  long steps = 0;        ///< accepted steps
  long rejected = 0;     ///< steps retried: error test or (implicit methods) Newton failures
  long evaluations = 0;  ///< right-hand sides (SUNDIALS, with difference-quotient Jacobians'), realizations (Simbody)
  double seconds = 0;    ///< wall time inside the integrator's steps (not the interpolation and realization at samples)
  long jacobians = 0;    ///< iteration-matrix evaluations (implicit methods; 0 for explicit ones; -1: not reported, CPodes)
};

/// Coordinates the integrator carries instead of Simbody's Y (sim/time/modal_links.hpp):
/// the integrator's y is theirs; they set the Simbody State from it.
class ReducedCoordinates {
 public:
  virtual ~ReducedCoordinates() = default;
  virtual int size() const = 0;
  /// y at the state `s` (the run's start).
  virtual void project(const SimTK::State& s, double* y) const = 0;
  /// Sets `s` to time t and y and writes y' into `ydot`. `full`: `s` is then realized to
  /// Acceleration with the reduced model's accelerations (a sample); else only as far
  /// as y' needs (a right-hand side). Throws on a Simbody failure.
  virtual void load(double t, const double* y, SimTK::State& s, double* ydot, bool full) const = 0;
  /// An approximation of dy'/dy at (t, y) for the implicit methods' Newton iteration
  /// (column-major, size() x size()); false: none, difference quotients instead. Only
  /// the iteration's convergence depends on it, not the solution.
  virtual bool jacobian(double t, const double* y, double* J) const {
    (void)t, (void)y, (void)J;
    return false;
  }
};

class ExternalStepper {
 public:
  virtual ~ExternalStepper() = default;
  virtual bool initialize(const SimTK::State& s, std::string& error) = 0;
  /// Advances to t; the state is then realized to Acceleration.
  virtual bool stepTo(double t, std::string& error) = 0;
  virtual const SimTK::State& state() const = 0;
  /// The run's end (sizes the first step; call before the first stepTo).
  virtual void setEndTime(double t) = 0;
  virtual IntegratorStats stats() const = 0;
};

/// The plugin's factory (extern "C").
/// `reduced`: null, or the coordinates to integrate (ODE methods only; kept by the caller).
using CreateStepper = ExternalStepper* (*)(const SimTK::MultibodySystem* system, int method, double relative_tolerance,
                                           double absolute_tolerance, const ReducedCoordinates* reduced);

/// The plugin's methods (codes as SundialsIntegrator::Method).
enum class SundialsMethod { CvodeAdams = 0, CvodeBdf = 1, ArkodeErk = 2, ArkodeDirk = 3, Ida = 4 };

/// Loads the SUNDIALS plugin and creates a stepper: CVODE BDF (dense Newton) or Adams
/// (fixed point), ARKODE explicit RK or implicit SDIRK (dense Newton), or IDA (a DAE that
/// holds closed trees' closures). Throws
/// UnavailableError if the plugin cannot be loaded (the message says where it was looked for).
/// `atol` <= 0: the relative tolerance (on the state's unit scale: rad, m, rad/s, m/s).
/// `reduced`: integrate those coordinates instead of Simbody's Y (not with IDA).
std::unique_ptr<ExternalStepper> makeSundialsStepper(const SimTK::MultibodySystem& system, SundialsMethod method,
                                                     double rtol, double atol = 0,
                                                     const ReducedCoordinates* reduced = nullptr);

}  // namespace mmv

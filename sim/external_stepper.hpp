#pragma once
/// An integrator that lives outside the main program: SUNDIALS CVODE is loaded from a
/// plugin (libmmvlab_cvode.so) with dlopen(RTLD_LOCAL | RTLD_DEEPBIND), because
/// Debian's libSimTKmath exports its own, older copy of SUNDIALS' N_Vector and CVODE
/// symbols (for Simbody's CPodes): linked into one program the two interpose on each
/// other and crash. Deep binding makes the plugin and SUNDIALS 6 resolve their symbols
/// among themselves first. Errors cross the boundary as strings, not exceptions.

#include <Simbody.h>

#include <memory>
#include <string>

namespace mmv {

class ExternalStepper {
 public:
  virtual ~ExternalStepper() = default;
  virtual bool initialize(const SimTK::State& s, std::string& error) = 0;
  /// Advances to t; the state is then realized to Acceleration.
  virtual bool stepTo(double t, std::string& error) = 0;
  virtual const SimTK::State& state() const = 0;
  virtual long steps() const = 0;
  virtual long evaluations() const = 0;  ///< right-hand-side evaluations
};

/// The plugin's factory (extern "C").
using CreateStepper = ExternalStepper* (*)(const SimTK::MultibodySystem* system, int bdf, double relative_tolerance);

/// Loads the CVODE plugin and creates a stepper (BDF with a dense Newton solver, or
/// Adams with fixed-point iteration). Throws NumericalError if the plugin cannot be
/// loaded (the message says where it was looked for).
std::unique_ptr<ExternalStepper> makeCvodeStepper(const SimTK::MultibodySystem& system, bool bdf, double rtol);

}  // namespace mmv

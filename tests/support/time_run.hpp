#pragma once
/// Test support: a sine dwell of the base
/// excitation table (scene `base: {type: table, motion: {type: sine, ...}}`) from the
/// static equilibrium, integrated by Simbody's CPodes (BDF, for the stiff hinge
/// dampers) to a steady state, and the complex amplitude of a point's absolute motion
/// over the table's: the measured transmissibility a swept-sine test would give at
/// that frequency, to set beside the linear model's FRF.

#include <complex>
#include <string>

#include "sim/scene/scene.hpp"

namespace mmv {

struct SineDwellOptions {
  std::string point;      ///< named point whose absolute motion is measured.
  int axis = 0;           ///< 0: x, 1: y.
  double settle_s = 20;   ///< s of transient before measuring.
  int cycles = 10;        ///< whole periods measured (Fourier coefficient over them).
  int samples_per_cycle = 64;
  double accuracy = 1e-7;  ///< integrator relative accuracy.
};

struct SineDwellResult {
  std::complex<double> transmissibility;  ///< point's motion over the table's, at the drive frequency.
  double drive_frequency_hz = 0;
  int steps = 0;
  double cpu_seconds = 0;
};

/// Test support (simulate() is the product's time run, closed trees included): open
/// trees only. Throws SceneError if the scene has no table motion or has closures,
/// NumericalError if the
/// equilibrium or the integration fails (or the state becomes non-finite).
SineDwellResult runSineDwell(const ArticleScene& scene, const SineDwellOptions& options);

}  // namespace mmv

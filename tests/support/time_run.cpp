#include "support/time_run.hpp"

#include <chrono>
#include <cmath>

#include "sim/model/article_builder.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {

SineDwellResult runSineDwell(const ArticleScene& scene, const SineDwellOptions& o) {
  const BaseSpec& base = scene.article.base;
  if (base.type != BaseType::Table || !base.motion || base.motion->type != TableMotion::Type::Sine)
    throw SceneError(scene.source + ": a sine dwell needs base: {type: table, motion: {type: sine, ...}}");
  // Closures are imposed by our statics and linearization, not by the Simbody system
  // the integrator advances: a closed tree would silently run open.
  if (!scene.article.closures.empty())
    throw SceneError(scene.source + ": the sine-dwell test helper runs open trees only");
  const auto t0 = std::chrono::steady_clock::now();
  const auto model = buildArticleModel(scene);
  const NamedPoint* p = model->findPoint(o.point);
  if (!p) throw SceneError(scene.source + ": unknown point '" + o.point + "'");
  const EquilibriumResult eq = solveEquilibrium(*model);
  if (!eq.converged) throw NumericalError("static equilibrium failed: " + eq.failure);

  const SimTK::MultibodySystem& system = model->getSystem();
  SimTK::State s = eq.state;
  system.realize(s, SimTK::Stage::Position);
  SimTK::CPodesIntegrator integ(system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
  integ.setAccuracy(o.accuracy);
  integ.setInternalStepLimit(1000000);  // many small steps between samples are fine
  SimTK::TimeStepper stepper(system, integ);
  stepper.initialize(s);

  const double f = base.motion->frequency_hz, w = 2 * M_PI * f, period = 1.0 / f;
  const double start = std::ceil(o.settle_s / period) * period;  // measure whole periods
  const int n = o.cycles * o.samples_per_cycle;
  std::complex<double> point_amp(0);
  for (int k = 0; k < n; ++k) {
    const double t = start + k * period / o.samples_per_cycle;
    if (stepper.stepTo(t) == SimTK::Integrator::EndOfSimulation || integ.isSimulationOver())
      throw NumericalError("sine dwell: the integrator stopped at t = " + std::to_string(integ.getTime()) + " s");
    const SimTK::State& st = integ.getState();
    const SimTK::Vec3 x = model->findPointLocation(st, *p);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1])) throw NumericalError("sine dwell: non-finite state at t = " + std::to_string(t) + " s");
    // Rectangle rule over whole periods: exact for the harmonics below the sampling rate.
    const std::complex<double> e = std::exp(std::complex<double>(0, -w * t));
    point_amp += x[o.axis] * e;
  }
  SineDwellResult r;
  r.drive_frequency_hz = f;
  // The table moves along x only: its complex amplitude is -i a (a sin = Im a e^{iwt}).
  const std::complex<double> table = std::complex<double>(0, -base.motion->amplitude) * (0.5 * n);
  r.transmissibility = point_amp / table;
  r.steps = integ.getNumStepsTaken();
  r.cpu_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace mmv

#include "sim/time/simulation.hpp"

/// A run's sampling loop (recordRun) and the judgements made of its record.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "sim/core/errors.hpp"
#include "sim/core/integrators.hpp"
#include "sim/time/run_integrator.hpp"

namespace mmv {

namespace {

/// Throws NumericalError naming the run when `row` holds a value that is not finite.
void checkFinite(const std::vector<double>& row, double t, const SimulationSpec& spec) {
  for (double v : row)
    if (!std::isfinite(v))
      throw NumericalError("non-finite state at t = " + std::to_string(t) + " s (" + spec.integrator + ", accuracy " +
                           std::to_string(spec.accuracy) + ")");
}

void takeCost(const RunIntegrator& integrator, SimulationResult& r, std::chrono::steady_clock::time_point start) {
  const IntegratorStats cost = integrator.stats();
  r.steps = static_cast<int>(cost.steps);
  r.realizations = static_cast<int>(cost.evaluations);
  r.rejected_steps = cost.rejected;
  r.jacobians = cost.jacobians;
  r.stepping_seconds = cost.seconds;
  r.output_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() - cost.seconds;
}

/// recordRun for SimulationSpec::scored_only: each sample's state realized to Position
/// and the row `sample` gives; no energy books (their midpoints are not stepped to).
void recordScoredOnly(const SimTK::MultibodySystem& sys, RunIntegrator& integrator, const SimulationSpec& spec, int n,
                      SimulationResult& r, const std::function<void(double)>& progress,
                      const std::function<std::vector<double>(double, const SimTK::State&)>& sample) {
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k <= n; ++k) {
    const double t = spec.duration * k / n;
    if (k > 0) integrator.stepTo(t);
    const SimTK::State& st = integrator.state();
    sys.realize(st, SimTK::Stage::Position);
    std::vector<double> row = sample(t, st);
    checkFinite(row, t, spec);
    r.record.rows.push_back(std::move(row));
    if (progress) progress(double(k) / n);
  }
  takeCost(integrator, r, start);
}

}  // namespace

void recordRun(const SimTK::MultibodySystem& sys, RunIntegrator& integrator, const SimulationSpec& spec,
               SimulationResult& r, const std::function<void(double)>& progress,
               const std::function<double(const SimTK::State&)>& input_power,
               const std::function<double(const SimTK::State&)>& dissipation,
               const std::function<std::vector<double>(double, const SimTK::State&)>& sample) {
  const SimTK::SimbodyMatterSubsystem& matter = sys.getMatterSubsystem();
  const int n = std::max(1, static_cast<int>(std::ceil(spec.duration * spec.sample_rate_hz)));
  integrator.setEndTime(spec.duration);
  if (spec.scored_only) return recordScoredOnly(sys, integrator, spec, n, r, progress, sample);
  // The work of the prescribed motions and inputs and the dissipation are integrated by
  // Simpson's rule on each sample interval, its midpoint an interpolated state (the
  // integrator's steps do not change): (w h)^4 / 2880 relative on a sinusoid. The
  // trapezoid on the samples alone was off by (w h)^2 / 12: 3 % of the work of a 10 Hz
  // table program at 200 samples/s, a balance error that no tolerance could remove.
  const auto power = [&](const SimTK::State& st) {
    return matter.calcMotionPower(st) + (input_power ? input_power(st) : 0.0);
  };
  const double h = spec.duration / n;
  double last_power = 0, last_dissipation = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k <= n; ++k) {
    const double t = spec.duration * k / n;
    double mid_power = 0, mid_dissipation = 0;
    if (k > 0) {
      integrator.stepTo(spec.duration * (k - 0.5) / n);
      mid_power = power(integrator.state());
      mid_dissipation = dissipation(integrator.state());
      integrator.stepTo(t);
    }
    const SimTK::State& st = integrator.state();
    sys.realize(st, SimTK::Stage::Acceleration);
    std::vector<double> row = sample(t, st);
    checkFinite(row, t, spec);
    const double p = power(st), d = dissipation(st);
    if (k == 0) {
      r.initial_energy_j = sys.calcEnergy(st);
    } else {
      r.motion_work_j += h / 6 * (last_power + 4 * mid_power + p);
      r.dissipated_j += h / 6 * (last_dissipation + 4 * mid_dissipation + d);
    }
    last_power = p, last_dissipation = d;
    r.final_energy_j = sys.calcEnergy(st);
    r.peak_kinetic_energy_j = std::max(r.peak_kinetic_energy_j, matter.calcKineticEnergy(st));
    const double balance = (r.final_energy_j - r.initial_energy_j) - (r.motion_work_j - r.dissipated_j);
    if (std::abs(balance) > std::abs(r.max_energy_balance_error_j))
      r.max_energy_balance_error_j = balance, r.max_energy_balance_error_at_s = t;
    r.record.rows.push_back(std::move(row));
    if (progress) progress(double(k) / n);
  }
  r.energy_balance_error_j = (r.final_energy_j - r.initial_energy_j) - (r.motion_work_j - r.dissipated_j);
  takeCost(integrator, r, start);
}

std::string constraintDriftWarning(const SimulationResult& r, double size_m) {
  if (!(r.constraint_drift_m > 1e-6 * size_m)) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "closure drift %.3g m exceeds 1e-6 of the article's size (%.3g m): %s", r.constraint_drift_m, size_m,
                !integratorInfo(r.integrator).projects_closures
                    ? "SUNDIALS' ODE methods do not project onto the closures; use a Simbody integrator or ida"
                    : "tighten the accuracy");
  return buf;
}

double energyScale(const SimulationResult& r) {
  return std::max({r.peak_kinetic_energy_j, std::abs(r.motion_work_j), std::abs(r.dissipated_j),
                   std::max(1e-8, r.accuracy) * std::max(std::abs(r.initial_energy_j), std::abs(r.final_energy_j))});
}

std::string energyBalanceWarning(const SimulationResult& r) {
  const double scale = energyScale(r), err = std::abs(r.max_energy_balance_error_j);
  if (err <= 0.01 * scale) return {};
  char buf[360];
  std::snprintf(buf, sizeof buf,
                "energy balance error %.3g J at t = %.4g s is %.3g %% of the run's energy scale %.3g J: the run is not "
                "accurate (tighten the accuracy, %.1e; for a trapezoidal slew also raise the sample rate)",
                err, r.max_energy_balance_error_at_s, scale > 0 ? 100 * err / scale : 100.0, scale, r.accuracy);
  return buf;
}

}  // namespace mmv

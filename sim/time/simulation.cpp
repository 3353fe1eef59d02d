#include "sim/time/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "sim/model/article_builder.hpp"
#include "facility/sensors.hpp"
#include "sim/statics/closures.hpp"
#include "sim/time/run_integrator.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {
namespace {

/// Power dissipated by the dampers, sum c u^2 (W).
double dissipation(const Model& model, const SimTK::State& s) {
  double p = 0;
  for (int i = 0; i < model.getNumCoordinates(); ++i) {
    const double c = model.getCoordinates()[i].damping;
    if (c > 0) p += c * std::pow(s.getU()[model.getUIndex(i)], 2);
  }
  return p;
}

}  // namespace

SimulationResult simulate(const ArticleScene& scene, const std::function<void(double)>& progress) {
  const SimulationSpec& spec = scene.simulation;
  const auto t0 = std::chrono::steady_clock::now();
  const auto model = buildArticleModel(scene);
  const SimTK::MultibodySystem& sys = model->getSystem();
  const auto& matter = model->getMatter();
  SimTK::State s = model->getReferenceState();
  if (spec.from_equilibrium) {
    const EquilibriumResult eq = solveEquilibrium(*model);
    if (!eq.converged) throw NumericalError("static equilibrium failed: " + eq.failure);
    s = eq.state;
  }
  s.updU() = 0;
  s.setTime(0);
  const bool closed = !model->getClosures().empty();
  if (closed) s = model->addClosureConstraints(s);  // the dynamics hold the closures from here
  RunIntegrator integrator(sys, spec.integrator, spec.accuracy, s, scene.source, spec.absolute_tolerance);

  SimulationResult r;
  r.integrator = spec.integrator;
  r.accuracy = spec.accuracy;
  // Columns.
  auto& cols = r.record.columns;
  cols.push_back("time_s");
  int table = -1;
  std::vector<int> joints;
  for (int i = 0; i < model->getNumCoordinates(); ++i) {
    const Coordinate& c = model->getCoordinates()[i];
    if (c.name == "table.x") table = i;
    if (c.kind == CoordinateKind::Joint && c.motion == CoordinateMotion::Rotation) joints.push_back(i);
  }
  if (table >= 0) {
    cols.push_back("table_x_m");
    cols.push_back("table_force_n");
    const SimTK::State& ref = model->getReferenceState();
    const double table_mass =
        matter.getMobilizedBody(model->getCoordinates()[table].mobod).getBodyMass(ref);
    r.carried_weight_n = (matter.calcSystemMass(ref) - table_mass) * model->getGravity().norm();
  }
  for (int j : joints) {
    cols.push_back(model->getCoordinates()[j].name + "_angle_deg");
    cols.push_back(model->getCoordinates()[j].name + "_torque_n_m");
  }
  std::vector<const NamedPoint*> tips;
  for (const auto& p : model->getPoints())
    if (p.name.size() > 4 && p.name.compare(p.name.size() - 4, 4, ".tip") == 0) {
      tips.push_back(&p);
      r.record.scored.push_back({p.name, {static_cast<int>(cols.size()), static_cast<int>(cols.size()) + 1}});
      cols.push_back(p.name + "_x_m");
      cols.push_back(p.name + "_y_m");
    }
  // Sensors: true signal -> facility model -> column.
  struct Live {
    facility::Sensor model;
    int joint = -1;             // encoder
    const NamedPoint* point = nullptr;  // gyro, accelerometer
    int axis = 0;
    bool gyro = false;
  };
  std::vector<Live> sensors;
  for (const auto& ss : scene.sensors) {
    facility::SensorSpec fs = ss.type == "encoder" ? facility::encoderSpec()
                              : ss.type == "rate_gyro" ? facility::rateGyroSpec()
                                                       : facility::accelerometerSpec();
    fs.noise_sigma = ss.noise_sigma;
    fs.seed = ss.seed;
    if (std::max(fs.high_cut_hz, fs.low_cut_hz) >= 0.5 * spec.sample_rate_hz)
      throw SceneError(ss.where + ": sensor '" + ss.name + "' has a band edge at " + std::to_string(fs.high_cut_hz) +
                       " Hz: simulation.sample_rate_hz must be above twice that (got " +
                       std::to_string(spec.sample_rate_hz) + ")");
    Live live{facility::Sensor(fs, spec.sample_rate_hz)};
    if (ss.type == "encoder") {
      for (int i = 0; i < model->getNumCoordinates(); ++i)
        if (model->getCoordinates()[i].name == ss.target) live.joint = i;
    } else {
      live.point = model->findPoint(ss.target);
    }
    if (live.joint < 0 && !live.point) throw SceneError(ss.where + ": sensor '" + ss.name + "': '" + ss.target + "' does not exist in the model");
    live.axis = ss.axis;
    live.gyro = ss.type == "rate_gyro";
    const char* unit = ss.type == "encoder" ? "rad" : ss.type == "rate_gyro" ? "rad_per_s" : "m_per_s2";
    cols.push_back(ss.name + "_" + unit);
    r.sensors.push_back({ss.name, ss.type, unit, 0, 0});
    sensors.push_back(std::move(live));
  }
  for (int j : joints) {
    JointTorqueSummary t;
    t.joint = model->getCoordinates()[j].name;
    t.capacity_nm = scene.article.torqueCapacity(t.joint);
    r.torques.push_back(t);
  }

  recordRun(sys, integrator, spec, r, progress, [&](const SimTK::State& st) { return model->inputPower(st); },
            [&](const SimTK::State& st) { return dissipation(*model, st); },
            [&](double t, const SimTK::State& st) {
    SimTK::Vector motion_forces;
    matter.findMotionForces(st, motion_forces);
    std::vector<double> row{t};
    if (table >= 0) {
      const double force = -motion_forces[model->getUIndex(table)];
      row.push_back(st.getQ()[model->getQIndex(table)]);
      row.push_back(force);
      r.peak_table_force_n = std::max(r.peak_table_force_n, std::abs(force));
    }
    for (std::size_t j = 0; j < joints.size(); ++j) {
      const int i = joints[j];
      // Simbody's motion force is the reaction; the torquer applies its negative
      // (checked against the static holding torque at t = 0); a commanded torque adds.
      const Coordinate& c = model->getCoordinates()[i];
      const double torque = -motion_forces[model->getUIndex(i)] + (c.input ? c.input->position(t) : 0.0);
      row.push_back(st.getQ()[model->getQIndex(i)] * 180 / M_PI);
      row.push_back(torque);
      r.torques[j].peak_torque_nm = std::max(r.torques[j].peak_torque_nm, std::abs(torque));
    }
    for (const NamedPoint* p : tips) {
      const SimTK::Vec3 x = model->findPointLocation(st, *p);
      row.push_back(x[0]);
      row.push_back(x[1]);
    }
    for (auto& live : sensors) {
      double truth;
      if (live.joint >= 0) {
        truth = st.getQ()[model->getQIndex(live.joint)];
      } else {
        const SimTK::MobilizedBody& mb = matter.getMobilizedBody(live.point->mobod);
        if (live.gyro) {
          truth = mb.getBodyAngularVelocity(st)[2];
        } else {
          const SimTK::Vec3 a_W = mb.findStationAccelerationInGround(st, live.point->station_B);
          const SimTK::Vec3 f_B = mb.getBodyRotation(st).transpose() * (a_W - model->getGravity());
          truth = f_B[live.axis];
        }
      }
      row.push_back(live.model.sample(truth));
    }
    if (closed) r.constraint_drift_m = std::max(r.constraint_drift_m, calcClosureErrors(*model, st).cwiseAbs().maxCoeff());
    return row;
  });
  for (auto& t : r.torques) t.exceeded = t.capacity_nm > 0 && t.peak_torque_nm > t.capacity_nm;
  for (std::size_t i = 0; i < sensors.size(); ++i) {
    r.sensors[i].saturated_samples = sensors[i].model.saturatedSamples();
    r.sensors[i].samples = sensors[i].model.samples();
  }
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

void recordRun(const SimTK::MultibodySystem& sys, RunIntegrator& integrator, const SimulationSpec& spec,
               SimulationResult& r, const std::function<void(double)>& progress,
               const std::function<double(const SimTK::State&)>& input_power,
               const std::function<double(const SimTK::State&)>& dissipation,
               const std::function<std::vector<double>(double, const SimTK::State&)>& sample) {
  const SimTK::SimbodyMatterSubsystem& matter = sys.getMatterSubsystem();
  const int n = std::max(1, static_cast<int>(std::ceil(spec.duration * spec.sample_rate_hz)));
  double last_motion_power = 0, last_dissipation = 0;
  for (int k = 0; k <= n; ++k) {
    const double t = spec.duration * k / n;
    if (k > 0) integrator.stepTo(t);
    const SimTK::State& st = integrator.state();
    sys.realize(st, SimTK::Stage::Acceleration);
    std::vector<double> row = sample(t, st);
    for (double v : row)
      if (!std::isfinite(v))
        throw NumericalError("non-finite state at t = " + std::to_string(t) + " s (" + spec.integrator + ", accuracy " +
                             std::to_string(spec.accuracy) + ")");
    // Energy bookkeeping (trapezoidal in time).
    const double motion_power = matter.calcMotionPower(st) + (input_power ? input_power(st) : 0.0);
    const double diss = dissipation(st);
    if (k == 0) {
      r.initial_energy_j = sys.calcEnergy(st);
    } else {
      const double dt = spec.duration / n;
      r.motion_work_j += 0.5 * dt * (motion_power + last_motion_power);
      r.dissipated_j += 0.5 * dt * (diss + last_dissipation);
    }
    last_motion_power = motion_power;
    last_dissipation = diss;
    r.final_energy_j = sys.calcEnergy(st);
    r.peak_kinetic_energy_j = std::max(r.peak_kinetic_energy_j, matter.calcKineticEnergy(st));
    r.record.rows.push_back(std::move(row));
    if (progress) progress(double(k) / n);
  }
  r.energy_balance_error_j = (r.final_energy_j - r.initial_energy_j) - (r.motion_work_j - r.dissipated_j);
  r.steps = integrator.steps();
  r.realizations = integrator.evaluations();
}

std::string constraintDriftWarning(const SimulationResult& r, double size_m) {
  if (!(r.constraint_drift_m > 1e-6 * size_m)) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "closure drift %.3g m exceeds 1e-6 of the article's size (%.3g m): %s", r.constraint_drift_m, size_m,
                isSundialsIntegrator(r.integrator) && r.integrator != "ida"
                    ? "SUNDIALS' ODE methods do not project onto the closures; use a Simbody integrator or ida"
                    : "tighten the accuracy");
  return buf;
}

double energyScale(const SimulationResult& r) {
  return std::max({r.peak_kinetic_energy_j, std::abs(r.motion_work_j), std::abs(r.dissipated_j),
                   1e-8 * std::max(std::abs(r.initial_energy_j), std::abs(r.final_energy_j))});
}

std::string energyBalanceWarning(const SimulationResult& r) {
  const double scale = energyScale(r), err = std::abs(r.energy_balance_error_j);
  if (err <= 0.01 * scale) return {};
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "energy balance error %.3g J is %.3g %% of the run's energy scale %.3g J: the run is not accurate "
                "(tighten the accuracy, %.1e; for a trapezoidal slew also raise the sample rate)",
                err, scale > 0 ? 100 * err / scale : 100.0, scale, r.accuracy);
  return buf;
}

}  // namespace mmv

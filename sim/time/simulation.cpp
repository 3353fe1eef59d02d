#include "sim/time/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

#include "sim/core/text.hpp"
#include "sim/model/article_builder.hpp"
#include "facility/sensors.hpp"
#include "sim/model/stations.hpp"
#include "sim/scene/stations.hpp"
#include "sim/statics/closures.hpp"
#include "sim/time/fidelity.hpp"
#include "sim/time/run_integrator.hpp"
#include "sim/statics/damping_matrix.hpp"
#include "sim/statics/linearize.hpp"
#include "sim/statics/statics.hpp"

namespace mmv {
namespace {

/// A sensor in a run: its facility model and what it reads.
struct LiveSensor {
  facility::Sensor model;
  int joint = -1;                     ///< encoder: the coordinate.
  std::optional<PointRef> point = {}; ///< gyro, accelerometer: a named point or a station.
  int axis = 0;
  bool gyro = false;
  std::optional<PointRef> span_end = {};  ///< strain: station B (`point` is A)
  double strain_scale = 0;            ///< strain: surface / span
  bool out_of_plane = false;          ///< strain: the +z face's (bending out of the plane)
};

/// The columns of an article's run and the row at each sample (see simulation.hpp).
class ArticleRecorder {
 public:
  ArticleRecorder(const Model& model, const ArticleScene& scene, SimulationResult& r)
      : model_(model), r_(r), scored_only_(scene.simulation.scored_only) {
    r_.record.columns.push_back("time_s");
    if (scored_only_) {  // a companion: the time and the scored points
      addTipColumns(scene);
      return;
    }
    addTableColumns();
    addShakerColumns(scene);
    addJointColumns(scene);
    addTipColumns(scene);
    addElasticColumns();
    addSensors(scene);
    stress_.emplace(model_, scene.article);
    for (const auto& c : stress_->columns()) r_.record.columns.push_back(c);
    r_.states.columns.push_back("time_s");
    for (const auto& c : model_.getCoordinates())
      r_.states.columns.push_back(c.name + (c.motion == CoordinateMotion::Rotation ? "_rad" : "_m"));
  }

  std::vector<double> sample(double t, const SimTK::State& st);
  void appendElastic(double t, const SimTK::State& st, std::vector<double>& row);
  /// The tips' and the scored stations' positions.
  void appendPoints(const SimTK::State& st, std::vector<double>& row) const;
  std::vector<double> scoredRow(double t, const SimTK::State& st) const;

  /// Peaks against capacities, sensor saturation counts, the links' stress.
  void finish() {
    if (stress_) r_.stresses = stress_->summary();
    for (auto& t : r_.torques) t.exceeded = t.capacity_nm > 0 && t.peak_torque_nm > t.capacity_nm;
    for (std::size_t i = 0; i < sensors_.size(); ++i) {
      r_.sensors[i].saturated_samples = sensors_[i].model.saturatedSamples();
      r_.sensors[i].samples = sensors_[i].model.samples();
    }
  }

 private:
  void addTableColumns();
  void addShakerColumns(const ArticleScene& scene);
  void appendShaker(double t, const SimTK::State& st, std::vector<double>& row);
  void addJointColumns(const ArticleScene& scene);
  void addTipColumns(const ArticleScene& scene);
  void addElasticColumns();
  void addSensors(const ArticleScene& scene);
  double sensorTruth(const LiveSensor& live, const SimTK::State& st) const;

  const Model& model_;
  SimulationResult& r_;
  const bool scored_only_;  ///< SimulationSpec::scored_only
  int table_ = -1, table_z_ = -1;
  int shaker_ = -1;            ///< the armature's coordinate (runs with shaker.program)
  double shaker_start_ = NAN;  ///< its position at the first sample
  double armature_kg_ = 0;
  std::vector<int> joints_;
  std::vector<const NamedPoint*> tips_;
  std::vector<PointRef> stations_;  ///< scored stations, after the tips
  std::vector<SimTK::QIndex> hinge_q_;  ///< every bending hinge's q: zero in `rigid_`
  std::optional<SimTK::State> rigid_;   ///< the sample's state with unbent links
  std::vector<LiveSensor> sensors_;
  std::optional<RunStress> stress_;  ///< not in a companion (scored_only)
};

void ArticleRecorder::addTableColumns() {
  auto& cols = r_.record.columns;
  for (int i = 0; i < model_.getNumCoordinates(); ++i) {
    if (model_.getCoordinates()[i].name == "table.x") table_ = i;
    if (model_.getCoordinates()[i].name == "table.z") table_z_ = i;
  }
  if (table_ < 0) return;
  cols.push_back("table_x_m");
  cols.push_back("table_force_n");
  if (table_z_ >= 0) {  // the stage across the plane (spatial model)
    cols.push_back("table_z_m");
    cols.push_back("table_z_force_n");
  }
  const SimTK::State& ref = model_.getReferenceState();
  const auto& matter = model_.getMatter();
  const double table_mass = matter.getMobilizedBody(model_.getCoordinates()[table_].mobod).getBodyMass(ref);
  double armature_mass = 0;  // on the shaker's stand, not the table
  for (const Coordinate& c : model_.getCoordinates())
    if (c.part == "shaker") armature_mass = matter.getMobilizedBody(c.mobod).getBodyMass(ref);
  r_.carried_weight_n = (matter.calcSystemMass(ref) - table_mass - armature_mass) * model_.getGravity().norm();
}

void ArticleRecorder::addShakerColumns(const ArticleScene& scene) {
  for (int i = 0; i < model_.getNumCoordinates(); ++i)
    if (model_.getCoordinates()[i].part == "shaker") shaker_ = i;
  if (shaker_ < 0) return;
  for (const char* c : {"shaker_force_n", "shaker_stroke_m", "shaker_stinger_force_n"}) r_.record.columns.push_back(c);
  const ShakerSceneSpec& sh = *scene.shaker;
  ShakerRunSummary s;
  s.at = sh.at;
  s.force_limit_n = sh.hardware.force_limit;
  s.stroke_m = sh.hardware.stroke;
  r_.shaker = s;
  armature_kg_ = sh.hardware.armature_mass;
}

/// The program's force, the armature's travel from the start and the stinger's force
/// (the program's less the armature's m a along the slider).
void ArticleRecorder::appendShaker(double t, const SimTK::State& st, std::vector<double>& row) {
  if (shaker_ < 0) return;
  const Coordinate& c = model_.getCoordinates()[shaker_];
  const double force = c.input->position(t);
  const double s = st.getQ()[model_.getQIndex(shaker_)];
  if (std::isnan(shaker_start_)) shaker_start_ = s;
  const double stroke = s - shaker_start_;
  const double stinger = force - armature_kg_ * st.getUDot()[model_.getUIndex(shaker_)];
  row.insert(row.end(), {force, stroke, stinger});
  ShakerRunSummary& sum = *r_.shaker;
  sum.peak_force_n = std::max(sum.peak_force_n, std::abs(force));
  sum.peak_stroke_m = std::max(sum.peak_stroke_m, std::abs(stroke));
  sum.peak_stinger_force_n = std::max(sum.peak_stinger_force_n, std::abs(stinger));
  sum.stroke_exceeded = sum.peak_stroke_m > sum.stroke_m;
}

void ArticleRecorder::addJointColumns(const ArticleScene& scene) {
  for (int i = 0; i < model_.getNumCoordinates(); ++i) {
    const Coordinate& c = model_.getCoordinates()[i];
    if (c.kind == CoordinateKind::Joint && c.motion == CoordinateMotion::Rotation) joints_.push_back(i);
  }
  for (int j : joints_) {
    r_.record.columns.push_back(model_.getCoordinates()[j].name + "_angle_deg");
    r_.record.columns.push_back(model_.getCoordinates()[j].name + "_torque_n_m");
  }
  for (int j : joints_) {
    JointTorqueSummary t;
    t.joint = model_.getCoordinates()[j].name;
    t.capacity_nm = scene.article.torqueCapacity(t.joint);
    r_.torques.push_back(t);
  }
}

void ArticleRecorder::addTipColumns(const ArticleScene& scene) {
  auto& cols = r_.record.columns;
  const bool spatial = model_.isSpatial();
  auto add = [&](const std::string& name) {
    const int first = static_cast<int>(cols.size());
    r_.record.scored.push_back({name, spatial ? std::vector<int>{first, first + 1, first + 2} : std::vector<int>{first, first + 1}});
    cols.push_back(name + "_x_m");
    cols.push_back(name + "_y_m");
    if (spatial) cols.push_back(name + "_z_m");  // out of the plane
  };
  for (const auto& p : model_.getPoints())
    if (p.name.size() > 4 && p.name.compare(p.name.size() - 4, 4, ".tip") == 0) {
      tips_.push_back(&p);
      add(p.name);
    }
  // Stations the scene (or a trade) scores: recorded beside the tips.
  for (const auto& name : scene.simulation.score_points) {
    if (!isStationName(name)) continue;
    std::string error;
    auto ref = PointRef::resolve(model_, scene.article, name, error);
    if (!ref) throw SceneError(scene.simulation.score_where + ": simulation.score_points: '" + name + "': " + error);
    stations_.push_back(std::move(*ref));
    add(name);
  }
}

/// Each tip's elastic deflection: where it is less where rigid links at the same joint
/// angles (table, gimbal and every joint as they are, every hinge unbent) would put it,
/// in that rigid tip's frame (along the link, across it in the plane, out of the plane):
/// what the flexibility adds to the motion, without the slew's metres (issue 36).
void ArticleRecorder::addElasticColumns() {
  for (int i = 0; i < model_.getNumCoordinates(); ++i)
    if (model_.getCoordinates()[i].kind == CoordinateKind::Hinge) hinge_q_.push_back(SimTK::QIndex(model_.getQIndex(i)));
  for (const NamedPoint* p : tips_) {
    r_.record.columns.push_back(p->name + "_elastic_along_m");
    r_.record.columns.push_back(p->name + "_elastic_across_m");
    if (model_.isSpatial()) r_.record.columns.push_back(p->name + "_elastic_out_m");
  }
}

/// Sensors: true signal -> facility model -> column.
void ArticleRecorder::addSensors(const ArticleScene& scene) {
  const SimulationSpec& spec = scene.simulation;
  for (const auto& ss : scene.sensors) {
    const facility::SensorSpec fs = sensorSpecOf(scene, ss);
    if (std::max(fs.high_cut_hz, fs.low_cut_hz) >= 0.5 * spec.sample_rate_hz)
      throw SceneError(ss.where + ": sensor '" + ss.name + "' has a band edge at " + std::to_string(fs.high_cut_hz) +
                       " Hz: simulation.sample_rate_hz must be above twice that (got " +
                       std::to_string(spec.sample_rate_hz) + ")");
    LiveSensor live{facility::Sensor(fs, spec.sample_rate_hz)};
    if (ss.type == "encoder") {
      for (int i = 0; i < model_.getNumCoordinates(); ++i)
        if (model_.getCoordinates()[i].name == ss.target) live.joint = i;
    } else {
      std::string error;
      live.point = PointRef::resolve(model_, scene.article, ss.target, error);
      if (!live.point) throw SceneError(ss.where + ": sensor '" + ss.name + "': " + error);
    }
    if (live.joint < 0 && !live.point)
      throw SceneError(ss.where + ": sensor '" + ss.name + "': '" + ss.target + "' does not exist in the model");
    live.axis = ss.axis;
    live.gyro = ss.type == "rate_gyro";
    if (ss.type == "strain") {
      std::string error;
      live.span_end = PointRef::resolve(model_, scene.article, ss.span_end, error);
      if (!live.span_end) throw SceneError(ss.where + ": sensor '" + ss.name + "': " + error);
      live.strain_scale = ss.surface_m / ss.span_m;
      live.out_of_plane = ss.out_of_plane;
    }
    const char* unit = ss.type == "encoder"     ? "rad"
                       : ss.type == "rate_gyro" ? "rad_per_s"
                       : ss.type == "strain"    ? "m_per_m"
                                                : "m_per_s2";
    r_.record.columns.push_back(ss.name + "_" + unit);
    r_.sensors.push_back({ss.name, ss.type, unit, 0, 0, fs.range});
    sensors_.push_back(std::move(live));
  }
}

double ArticleRecorder::sensorTruth(const LiveSensor& live, const SimTK::State& st) const {
  if (live.joint >= 0) return st.getQ()[model_.getQIndex(live.joint)];
  if (live.gyro) return live.point->angularRate(st, live.axis);
  // The mean curvature over the span times the face's distance: the turn of the axis from
  // A to B (exact for any rotation, as the linear model's theta_B - theta_A is to first order).
  if (live.span_end) return strainReading(*live.point, *live.span_end, st, live.strain_scale, live.out_of_plane);
  const SimTK::Vec3 f_W = live.point->acceleration(st) - model_.getGravity();  // specific force
  return ~f_W * live.point->localAxis(st, live.axis);
}

void ArticleRecorder::appendPoints(const SimTK::State& st, std::vector<double>& row) const {
  const int dims = model_.isSpatial() ? 3 : 2;
  for (const NamedPoint* p : tips_) {
    const SimTK::Vec3 x = model_.findPointLocation(st, *p);
    for (int k = 0; k < dims; ++k) row.push_back(x[k]);
  }
  for (const auto& p : stations_) {
    const SimTK::Vec3 x = p.position(st);
    for (int k = 0; k < dims; ++k) row.push_back(x[k]);
  }
}

std::vector<double> ArticleRecorder::scoredRow(double t, const SimTK::State& st) const {
  std::vector<double> row{t};
  row.reserve(r_.record.columns.size());
  appendPoints(st, row);
  return row;
}

void ArticleRecorder::appendElastic(double t, const SimTK::State& st, std::vector<double>& row) {
  if (tips_.empty()) return;
  if (!rigid_) rigid_ = st;  // same topology as the run's states from here on
  rigid_->setTime(t);
  rigid_->updQ() = st.getQ();
  for (SimTK::QIndex q : hinge_q_) rigid_->updQ()[q] = 0;
  model_.getSystem().realize(*rigid_, SimTK::Stage::Position);
  const int dims = model_.isSpatial() ? 3 : 2;
  for (const NamedPoint* p : tips_) {
    const SimTK::Vec3 d_W = model_.findPointLocation(st, *p) - model_.findPointLocation(*rigid_, *p);
    const SimTK::Vec3 d_B = ~model_.getMatter().getMobilizedBody(p->mobod).getBodyRotation(*rigid_) * d_W;
    for (int k = 0; k < dims; ++k) row.push_back(d_B[k]);
  }
}

std::vector<double> ArticleRecorder::sample(double t, const SimTK::State& st) {
  if (scored_only_) return scoredRow(t, st);
  SimTK::Vector motion_forces;
  model_.getMatter().findMotionForces(st, motion_forces);
  std::vector<double> row{t};
  if (table_ >= 0) {
    const double force = -motion_forces[model_.getUIndex(table_)];
    row.push_back(st.getQ()[model_.getQIndex(table_)]);
    row.push_back(force);
    r_.peak_table_force_n = std::max(r_.peak_table_force_n, std::abs(force));
    if (table_z_ >= 0) {
      const double force_z = -motion_forces[model_.getUIndex(table_z_)];
      row.push_back(st.getQ()[model_.getQIndex(table_z_)]);
      row.push_back(force_z);
      r_.peak_table_force_n = std::max(r_.peak_table_force_n, std::abs(force_z));  // either axis's actuator
    }
  }
  appendShaker(t, st, row);
  for (std::size_t j = 0; j < joints_.size(); ++j) {
    const int i = joints_[j];
    // Simbody's motion force is the reaction; the torquer applies its negative
    // (checked against the static holding torque at t = 0); a commanded torque adds.
    const Coordinate& c = model_.getCoordinates()[i];
    const double torque = -motion_forces[model_.getUIndex(i)] + (c.input ? c.input->position(t) : 0.0);
    row.push_back(st.getQ()[model_.getQIndex(i)] * 180 / M_PI);
    row.push_back(torque);
    r_.torques[j].peak_torque_nm = std::max(r_.torques[j].peak_torque_nm, std::abs(torque));
  }
  appendPoints(st, row);
  appendElastic(t, st, row);
  for (auto& live : sensors_) row.push_back(live.model.sample(sensorTruth(live, st)));
  std::vector<double> q{t};
  for (int i = 0; i < model_.getNumCoordinates(); ++i) q.push_back(st.getQ()[model_.getQIndex(i)]);
  stress_->sample(t, st, Eigen::Map<const Eigen::VectorXd>(q.data() + 1, model_.getNumCoordinates()), row);
  r_.states.rows.push_back(std::move(q));
  if (!model_.getClosures().empty())
    r_.constraint_drift_m = std::max(r_.constraint_drift_m, calcClosureErrors(model_, st).cwiseAbs().maxCoeff());
  return row;
}

/// The scene's modal or Rayleigh damping as the damping matrix of the linear models,
/// formed at the equilibrium `eq` (every mode of it gets its ratio) and held constant in
/// the coordinates through the run.
void setDampingMatrix(Model& model, const DampingSpec& damping, const EquilibriumResult& eq) {
  const LinearizedModel lin = linearize(model, eq.state, eq.closure_multipliers);
  model.setLinearDamping(lin.dofs, calcDampingMatrix(lin, damping));
}

/// The run's start: the static equilibrium (or the scene's angles) at rest, with the
/// closures as constraints from here on, and the damping matrix (if the scene has one)
/// formed at the equilibrium.
SimTK::State initialState(Model& model, const SimulationSpec& spec, const std::optional<DampingSpec>& damping,
                          std::vector<std::string>& warnings) {
  SimTK::State s = model.getReferenceState();
  const bool matrix_damping = model.hasLinearDamper() && damping && isMatrixDamping(*damping);
  std::optional<EquilibriumResult> solved;
  if (spec.from_equilibrium || matrix_damping) {
    solved = solveEquilibrium(model);
    if (!solved->converged)
      throw NumericalError("static equilibrium failed" +
                           std::string(spec.from_equilibrium ? "" : " (the damping matrix is formed there)") + ": " +
                           solved->failure);
    if (matrix_damping) setDampingMatrix(model, *damping, *solved);
  }
  if (spec.from_equilibrium) {
    const EquilibriumResult& eq = *solved;
    s = eq.state;
    const EquilibriumAssessment a = assessEquilibrium(model, eq);
    for (const auto& m : a.moved_joints) warnings.push_back("the start is the static equilibrium nearest the scene's angles: " + m);
    if (a.unstable_directions > 0)
      warnings.push_back(strf("the start is an unstable equilibrium (%d direction(s) of negative stiffness, e.g. an inverted "
                              "pendulum): the article stays there, at rest, only until round-off grows; to see it fall, "
                              "start at rest (simulation.start: rest) or from a disturbed angle",
                              a.unstable_directions));
  }
  s.updU() = 0;
  s.setTime(0);
  if (!model.getClosures().empty()) {
    s = model.addClosureConstraints(s);
    s.setTime(0);
    model.startClosureSpeeds(s);
  }
  return s;
}

}  // namespace

SimulationResult simulate(const ArticleScene& asked, const std::function<void(double)>& progress) {
  ArticleScene scene = asked;
  const FidelityChoice fidelity = resolveFidelity(scene);
  const SimulationSpec& spec = scene.simulation;
  const auto t0 = std::chrono::steady_clock::now();
  const auto model = buildArticleModel(scene, ModelUse::TimeRun);
  SimulationResult r;
  r.fidelity = fidelity.reason;
  SimTK::State s = initialState(*model, spec, scene.damping, r.warnings);
  std::unique_ptr<ModalLinks> modal;  // links in modal coordinates
  if (!model->getReducedMotions().empty()) {
    model->getSystem().realize(s, SimTK::Stage::Position);
    modal = std::make_unique<ModalLinks>(*model, scene.article, s);
    r.modal_links = modal->summary();
    model->getReducedMotions().enable(model->getMatter(), s);
  }
  RunIntegrator integrator(model->getSystem(), spec.integrator, spec.accuracy, s, scene.source, spec.absolute_tolerance,
                           modal.get());
  r.integrator = spec.integrator;
  r.accuracy = spec.accuracy;
  r.damping = !scene.damping ? "none (the scene has no damping:)"
              : isMatrixDamping(*scene.damping)
                  ? describeDamping(*scene.damping) + ", its damping matrix formed at the static equilibrium"
                  : describeDamping(*scene.damping);
  ArticleRecorder recorder(*model, scene, r);
  recordRun(model->getSystem(), integrator, spec, r, progress, [&](const SimTK::State& st) { return model->inputPower(st); },
            [&](const SimTK::State& st) { return model->calcDissipation(st); },
            [&](double t, const SimTK::State& st) { return recorder.sample(t, st); });
  recorder.finish();
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}


}  // namespace mmv

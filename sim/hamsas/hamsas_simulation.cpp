#include "sim/hamsas/hamsas_simulation.hpp"

#include <Simbody.h>

#include <chrono>
#include <cmath>

#include "sim/model/motions.hpp"
#include "sim/time/run_integrator.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {

SimTK::Vec3 vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

SimTK::Vec3 times(const SimTK::Vec3& a, const SimTK::Vec3& b) { return {a[0] * b[0], a[1] * b[1], a[2] * b[2]}; }

/// Every spring and damper of the network, with exact kinematics.
class SpatialElements : public SimTK::Force::Custom::Implementation {
 public:
  SpatialElements(const SimTK::SimbodyMatterSubsystem& matter, const SpatialSpec& spec,
                  const SpatialLinearization& lin, std::vector<SimTK::MobilizedBodyIndex> mobods)
      : matter_(matter), spec_(spec), mobods_(std::move(mobods)) {
    for (std::size_t e = 0; e < spec.springs.size(); ++e) {
      const PointSpring& sp = spec.springs[e];
      // Force on b is -K (d - d0); at the design (d = 0) it must be the preload, -g.
      rest_.push_back(vec(-lin.spring_force[e].cwiseQuotient(sp.stiffness)));
      station_a_.push_back(vec(sp.point - origin(sp.a)));
      station_b_.push_back(vec(sp.point - origin(sp.b)));
    }
    for (std::size_t e = 0; e < spec.angular.size(); ++e) {
      SimTK::Vec3 phi0(0);
      for (int k = 0; k < 3; ++k)
        if (spec.angular[e].stiffness[k] > 0) phi0[k] = -lin.angular_moment[e][k] / spec.angular[e].stiffness[k];
      rest_angle_.push_back(phi0);
    }
  }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& body_forces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector&) const override {
    for (std::size_t e = 0; e < spec_.springs.size(); ++e) {
      const PointSpring& sp = spec_.springs[e];
      const auto& a = body(sp.a);
      const auto& b = body(sp.b);
      const SimTK::Vec3 d = b.findStationLocationInGround(s, station_b_[e]) - a.findStationLocationInGround(s, station_a_[e]);
      const SimTK::Vec3 v = b.findStationVelocityInGround(s, station_b_[e]) - a.findStationVelocityInGround(s, station_a_[e]);
      const SimTK::Vec3 f = -(times(vec(sp.stiffness), d - rest_[e]) + times(vec(sp.damping), v));
      b.applyForceToBodyPoint(s, station_b_[e], f, body_forces);
      a.applyForceToBodyPoint(s, station_a_[e], -f, body_forces);
    }
    for (std::size_t e = 0; e < spec_.angular.size(); ++e) {
      const AngularSpring& as = spec_.angular[e];
      const auto& a = body(as.a);
      const auto& b = body(as.b);
      const SimTK::Vec3 w = b.getBodyAngularVelocity(s) - a.getBodyAngularVelocity(s);
      const SimTK::Vec3 t = -(times(vec(as.stiffness), relativeRotation(s, e) - rest_angle_[e]) + times(vec(as.damping), w));
      b.applyBodyTorque(s, t, body_forces);
      a.applyBodyTorque(s, -t, body_forces);
    }
  }

  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    double V = 0;
    for (std::size_t e = 0; e < spec_.springs.size(); ++e) {
      const PointSpring& sp = spec_.springs[e];
      const SimTK::Vec3 d = body(sp.b).findStationLocationInGround(s, station_b_[e]) -
                            body(sp.a).findStationLocationInGround(s, station_a_[e]) - rest_[e];
      V += 0.5 * ~d * times(vec(sp.stiffness), d);
    }
    for (std::size_t e = 0; e < spec_.angular.size(); ++e) {
      const SimTK::Vec3 p = relativeRotation(s, e) - rest_angle_[e];
      V += 0.5 * ~p * times(vec(spec_.angular[e].stiffness), p);
    }
    return V;
  }

  /// Power the dampers dissipate (W).
  double dissipation(const SimTK::State& s) const {
    double p = 0;
    for (std::size_t e = 0; e < spec_.springs.size(); ++e) {
      const PointSpring& sp = spec_.springs[e];
      const SimTK::Vec3 v = body(sp.b).findStationVelocityInGround(s, station_b_[e]) -
                            body(sp.a).findStationVelocityInGround(s, station_a_[e]);
      p += ~v * times(vec(sp.damping), v);
    }
    for (std::size_t e = 0; e < spec_.angular.size(); ++e) {
      const AngularSpring& as = spec_.angular[e];
      const SimTK::Vec3 w = body(as.b).getBodyAngularVelocity(s) - body(as.a).getBodyAngularVelocity(s);
      p += ~w * times(vec(as.damping), w);
    }
    return p;
  }

  bool dependsOnlyOnPositions() const override { return false; }

 private:
  Eigen::Vector3d origin(int body) const { return body == 0 ? spec_.reference : spec_.bodies[body].com; }
  const SimTK::MobilizedBody& body(int i) const { return matter_.getMobilizedBody(mobods_[i]); }
  /// The rotation vector (angle times axis) of R_b R_a^T, world axes.
  SimTK::Vec3 relativeRotation(const SimTK::State& s, std::size_t e) const {
    const AngularSpring& as = spec_.angular[e];
    const SimTK::Rotation r = body(as.b).getBodyRotation(s) * ~body(as.a).getBodyRotation(s);
    const SimTK::Vec4 aa = r.convertRotationToAngleAxis();
    return aa[0] * SimTK::Vec3(aa[1], aa[2], aa[3]);
  }

  const SimTK::SimbodyMatterSubsystem& matter_;
  SpatialSpec spec_;
  std::vector<SimTK::MobilizedBodyIndex> mobods_;
  std::vector<SimTK::Vec3> rest_, station_a_, station_b_, rest_angle_;
};

/// states.csv of an isolator run: every body's motion from the design (the base's is
/// the ground's), to redraw the run.
std::vector<std::string> bodyMotionColumns(const SpatialSpec& model) {
  std::vector<std::string> cols{"time_s"};
  for (const auto& body : model.bodies)
    for (const char* q : {"_x_m", "_y_m", "_z_m", "_rx_rad", "_ry_rad", "_rz_rad"}) cols.push_back(body.name + q);
  return cols;
}

std::vector<double> bodyMotionRow(const SimTK::SimbodyMatterSubsystem& matter, const std::vector<SimTK::MobilizedBodyIndex>& mobods,
                                  const SpatialSpec& model, int ground_axis, double ground, double t, const SimTK::State& st) {
  std::vector<double> q{t};
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    SimTK::Vec3 x(0), w(0);
    if (b == 0) {
      x[ground_axis] = ground;
    } else {
      const auto& mb = matter.getMobilizedBody(mobods[b]);
      x = mb.getBodyOriginLocation(st) - vec(model.bodies[b].com);
      const SimTK::Vec4 aa = mb.getBodyRotation(st).convertRotationToAngleAxis();
      w = aa[0] * SimTK::Vec3(aa[1], aa[2], aa[3]);
    }
    q.insert(q.end(), {x[0], x[1], x[2], w[0], w[1], w[2]});
  }
  return q;
}

/// What a HAM-SAS run integrates (its `Model:` line): the one model it has.
std::string runFidelity(const SpatialSpec& model, const HamsasSpec& hs) {
  return strf("the base on the ground's program and %zu rigid bodies, each free in space, joined by the isolator's "
              "springs (the effective spherical joints as %.3g N/m springs, spherical_joints: stiff): the authors' MBDyn "
              "model, nothing to discretize",
              model.bodies.size() - 1, hs.joint_stiffness);
}

}  // namespace

SimulationResult simulate(const HamsasScene& scene, const std::function<void(double)>& progress) {
  const HamsasSpec& hs = scene.isolator;
  if (!scene.ground_motion)
    throw SceneError(scene.positions.where("ground_motion") + ": a HAM-SAS time run needs `ground_motion:` (a program and its axis; docs/hamsas.md)");
  if (hs.ideal_joints)
    throw SceneError(scene.positions.where("hamsas.spherical_joints") + ": HAM-SAS time runs use the stiff effective joints (spherical_joints: stiff)");
  const SimulationSpec& spec = scene.simulation;
  const auto t0 = std::chrono::steady_clock::now();
  const SpatialSpec model = buildHamsas(hs);
  const SpatialLinearization lin = linearizeSpatial(model, false);

  SimTK::MultibodySystem sys;
  SimTK::SimbodyMatterSubsystem matter(sys);
  SimTK::GeneralForceSubsystem forces(sys);
  SimTK::Force::UniformGravity(forces, matter, vec(model.gravity));
  // The base slides along the ground motion's axis: F's x is that axis, and the body
  // frame turns back so the base's axes stay the world's.
  const SimTK::Rotation to_axis = scene.ground_axis == 0   ? SimTK::Rotation()
                                  : scene.ground_axis == 1 ? SimTK::Rotation(M_PI / 2, SimTK::ZAxis)
                                                           : SimTK::Rotation(-M_PI / 2, SimTK::YAxis);
  SimTK::MobilizedBody::Slider base(matter.Ground(), SimTK::Transform(to_axis, vec(model.reference)),
                                    SimTK::Body::Rigid(SimTK::MassProperties(1.0, SimTK::Vec3(0), SimTK::Inertia(1.0))),
                                    SimTK::Transform(to_axis));
  const auto program = makeTableProgram(*scene.ground_motion);
  prescribeTableProgram(base, program);
  std::vector<SimTK::MobilizedBodyIndex> mobods{base.getMobilizedBodyIndex()};
  for (std::size_t b = 1; b < model.bodies.size(); ++b) {
    const SpatialBody& sb = model.bodies[b];
    const Eigen::Matrix3d& I = sb.inertia;
    const SimTK::Body::Rigid body(SimTK::MassProperties(
        sb.mass, SimTK::Vec3(0), SimTK::Inertia(I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2))));
    SimTK::MobilizedBody::Free free(matter.Ground(), SimTK::Transform(vec(sb.com)), body, SimTK::Transform());
    mobods.push_back(free.getMobilizedBodyIndex());
  }
  auto* elements = new SpatialElements(matter, model, lin, mobods);
  SimTK::Force::Custom(forces, elements);
  sys.realizeTopology();
  SimTK::State s = sys.getDefaultState();
  s.setTime(0);
  sys.realize(s, SimTK::Stage::Position);
  RunIntegrator integrator(sys, spec.integrator, spec.accuracy, s, scene.source, spec.absolute_tolerance);

  SimulationResult r;
  r.integrator = spec.integrator;
  r.accuracy = spec.accuracy;
  r.fidelity = runFidelity(model, hs);
  auto& cols = r.record.columns;
  const char* axes[] = {"x", "y", "z"};
  cols = {"time_s", std::string("ground_") + axes[scene.ground_axis] + "_m"};
  for (int b : {1, 2}) {
    const std::string name = model.bodies[b].name;
    r.record.scored.push_back({name, {static_cast<int>(cols.size()), static_cast<int>(cols.size()) + 1,
                                      static_cast<int>(cols.size()) + 2}});
    for (const char* a : axes) cols.push_back(name + "_" + a + "_m");
  }
  for (const auto& sensor : model.sensors) cols.push_back("sensor_" + sensor.name + "_m");
  r.states.columns = bodyMotionColumns(model);

  recordRun(sys, integrator, spec, r, progress, {}, [&](const SimTK::State& st) { return elements->dissipation(st); },
            [&](double t, const SimTK::State& st) {
    std::vector<double> row{t, program->position(t)};
    for (int b : {1, 2}) {
      const SimTK::Vec3 x = matter.getMobilizedBody(mobods[b]).getBodyOriginLocation(st) - vec(model.bodies[b].com);
      row.insert(row.end(), {x[0], x[1], x[2]});
    }
    for (const auto& sensor : model.sensors) {
      const auto& a = matter.getMobilizedBody(mobods[sensor.a]);
      const auto& b = matter.getMobilizedBody(mobods[sensor.b]);
      const Eigen::Vector3d oa = sensor.a == 0 ? model.reference : model.bodies[sensor.a].com;
      const SimTK::Vec3 d = b.findStationLocationInGround(st, vec(sensor.point - model.bodies[sensor.b].com)) -
                            a.findStationLocationInGround(st, vec(sensor.point - oa));
      row.push_back(~d * vec(sensor.direction));
    }
    r.states.rows.push_back(bodyMotionRow(matter, mobods, model, scene.ground_axis, program->position(t), t, st));
    return row;
  });
  r.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

TradeProblem hamsasTradeProblem(const HamsasScene& base, double duration) {
  TradeProblem p = tradeProblemBase(base.name, base.simulation, duration);
  HamsasScene scene = base;
  scene.simulation = p.simulation;
  const SpatialSpec model = buildHamsas(scene.isolator);
  for (int b : {1, 2}) p.scorable.push_back(model.bodies[b].name);  // the bodies simulate() scores
  p.scorable_kind = "scored body";
  p.reference_integrator = "rk_merson";
  p.check_integrator = "arkode_erk";
  p.has_segments = false;
  p.run = [scene](const SimulationSpec& spec, const RunFidelity&, const std::function<void(double)>& progress) {
    HamsasScene s = scene;
    s.simulation = spec;
    return simulate(s, progress);
  };
  return p;
}

}  // namespace mmv

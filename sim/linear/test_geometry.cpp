#include "sim/linear/test_geometry.hpp"

#include <optional>

#include "sim/core/errors.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/damping.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

const char* const kBaseNode = "base";

namespace {

void addNode(TestGeometry& g, const std::string& name, const std::array<double, 3>& xyz) {
  const int id = static_cast<int>(g.nodes.size()) + 1;
  g.id_of[name] = id;
  g.nodes.push_back({id, name, xyz});
}

/// The first `count` modes' shapes at the mesh points: each mode's velocity pass over the
/// tree (Model::calcFrameVelocities, O(bodies)), not every point's Jacobian (O(points x
/// depth x DOF), 6 % of frf at 64 segments a link, for twelve products).
void addShapes(const LinearModel& lm, const SimTK::State& st, int count, TestGeometry& g) {
  const Model& model = *lm.solved.model;
  std::vector<SimTK::MobilizedBodyIndex> bodies;
  std::vector<SimTK::Vec3> stations;
  for (const auto& p : model.getPoints()) {
    bodies.push_back(p.mobod);
    stations.push_back(p.station_B);
  }
  const ModalSolution& modes = lm.solved.modes;
  const int n = std::min<int>(count, static_cast<int>(modes.omega2.size()));
  const ModalDamping damping = modalDamping(model, lm.solved.linearized, modes, lm.damping, n);
  const bool spatial = model.isSpatial();
  for (int k = 0; k < n; ++k) {
    TestModeShape m;
    m.mode = ModeNumber::atIndex(k);
    m.frequency_hz = modes.frequencyHz(k);
    m.damping_ratio = k < static_cast<int>(damping.ratio.size()) ? damping.ratio[k] : 0.0;
    // Rows 6p..6p+2: the point's body rotation; 6p+3..6p+5: the point's translation.
    const Eigen::VectorXd v = model.calcFrameVelocities(st, bodies, stations, lm.solved.linearized.dofs, modes.shapes.col(k));
    for (std::size_t p = 0; p < bodies.size(); ++p) {
      m.translation.push_back({v[6 * p + 3], v[6 * p + 4], spatial ? v[6 * p + 5] : 0.0});
      m.rotation.push_back({v[6 * p], v[6 * p + 1], v[6 * p + 2]});
    }
    g.modes.push_back(m);
  }
}

}  // namespace

TestGeometry linearTestGeometry(const LinearModel& lm, const ArticleScene& scene, int modes) {
  const Model& model = *lm.solved.model;
  TestGeometry g;
  SimTK::State st = lm.solved.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  for (const auto& p : model.getPoints()) {
    const SimTK::Vec3 x = model.findPointLocation(st, p);
    addNode(g, p.name, {x[0], x[1], x[2]});
  }
  g.mesh_points = static_cast<int>(g.nodes.size());
  // Stations the functions refer to are nodes too, after the mesh's points.
  std::vector<std::string> used;
  for (const auto& out : lm.outputs) used.push_back(out.point);
  for (const auto& in : lm.inputs)
    if (in.kind == InputKind::PointForce || in.kind == InputKind::PointMoment) used.push_back(in.target);
  for (const auto& name : used) {
    if (g.id_of.count(name)) continue;
    std::string error;
    const std::optional<PointRef> p = PointRef::resolve(model, scene.article, name, error);
    MMV_DEMAND(p.has_value());  // the linear model resolved it already
    const SimTK::Vec3 x = p->position(st);
    addNode(g, name, {x[0], x[1], x[2]});
  }
  const auto& b = scene.article.base.position;
  addNode(g, kBaseNode, {b[0], b[1], b[2]});
  int trace = 1;
  for (const auto& l : scene.article.links) {
    TestTrace t{trace++, l.name, {}};
    t.nodes.push_back(g.id_of.at(l.name + ".root"));
    for (int k = 1; !l.rigid && k <= l.segments; ++k) t.nodes.push_back(g.id_of.at(l.name + ".h" + std::to_string(k)));
    t.nodes.push_back(g.id_of.at(l.name + ".tip"));
    g.traces.push_back(t);
  }
  addShapes(lm, st, modes, g);
  return g;
}

}  // namespace mmv

#include "sim/model/attachments.hpp"

#include <algorithm>
#include <cmath>

#include "sim/model/stations.hpp"

#include "sim/core/errors.hpp"
#include "sim/scene/programs.hpp"
#include "sim/scene/stations.hpp"

namespace mmv {
namespace {

const NamedPoint& requirePoint(const Model& model, const std::string& name, const std::string& where,
                               const std::string& what) {
  const NamedPoint* p = model.findPoint(name);
  // The scene reader checked the name; only a --segments override can remove a hinge.
  if (!p) throw SceneError(where + ": " + what + " '" + name + "' does not exist with the segment counts in use");
  return *p;
}

}  // namespace

void addLoadsAndClosures(const ArticleSpec& a, Model& model) {
  for (std::size_t i = 0; i < a.loads.size(); ++i) {
    const LoadSpec& l = a.loads[i];
    const NamedPoint& p = requirePoint(model, l.point, l.where, "loads[" + std::to_string(i) + "].point");
    model.addPointLoad({p.mobod, p.station_B, SimTK::Vec3(l.force[0], l.force[1], l.force[2])});
  }
  for (std::size_t i = 0; i < a.closures.size(); ++i) {
    const ClosureSpec& cs = a.closures[i];
    const std::string path = "closures[" + std::to_string(i) + "]";
    const NamedPoint& pa = requirePoint(model, cs.point, cs.where, path + ".point");
    Closure c;
    c.name = cs.name;
    c.where = cs.where;
    c.mobod_a = pa.mobod;
    c.station_a = pa.station_B;
    if (cs.to != "ground") {
      const NamedPoint& pb = requirePoint(model, cs.to, cs.where, path + ".to");
      c.to_ground = false;
      c.mobod_b = pb.mobod;
      c.station_b = pb.station_B;
    } else if (cs.at) {
      c.has_anchor = true;
      c.anchor_W = SimTK::Vec3((*cs.at)[0], (*cs.at)[1], (*cs.at)[2]);
    }
    if (cs.type == ClosureType::Pin) {
      c.directions = {SimTK::Vec3(1, 0, 0), SimTK::Vec3(0, 1, 0)};
    } else {  // held across the line: its normal
      c.directions = {SimTK::Vec3(-std::sin(cs.direction), std::cos(cs.direction), 0)};
    }
    // Spatial: the point is held out of the plane too (a pin is a ball joint, a slider
    // holds the point on its line) wherever the article can move it there (not when
    // the chain to it bends in the plane only); the rotations stay free, as in the plane.
    c.hold_z_if_free = a.model == ArticleModel::Spatial;
    model.addClosure(c);
  }
}

void addShakerArmature(const ArticleScene& scene, Model& model) {
  const ShakerSceneSpec& sh = *scene.shaker;
  MMV_DEMAND(sh.program && !sh.autoAt() && sh.hardware.armature_mass > 0);
  std::string error;
  const std::optional<StationSpec> st = parseStation(sh.at, scene.article, error);
  if (!st) throw SceneError(scene.positions.where("shaker.at") + ": shaker.at: " + error);
  const LinkAxis* axis = model.findLinkAxis(st->link);
  MMV_DEMAND(axis != nullptr && axis->x.size() >= 2);
  const std::size_t k = axis->nodeBefore(st->x);
  const SimTK::MobilizedBodyIndex piece = axis->right[k];
  const SimTK::Vec3 station_B(st->x - axis->x[k], 0, 0);  // a piece's frame starts at its node, x along the link

  const SimTK::UnitVec3 d(SimTK::Vec3(sh.direction[0], sh.direction[1], sh.direction[2]));
  const double m = sh.hardware.armature_mass;
  const int part = model.addPart("shaker", Part::Kind::Shaker, "");
  // The slider's x axis along the force, from the ground origin; finalize moves the
  // armature to the driving point (Closure::fit_coordinate).
  const SimTK::Transform X_GF(SimTK::Rotation(d, SimTK::XAxis), SimTK::Vec3(0));
  SimTK::MobilizedBody::Slider armature(model.updMatter().updGround(), X_GF,
                                        SimTK::Body::Rigid(SimTK::MassProperties(m, SimTK::Vec3(0), SimTK::Inertia(0))),
                                        SimTK::Transform(X_GF.R()));
  model.addBody(armature.getMobilizedBodyIndex(), part, false);
  Coordinate c = sliderCoordinate("shaker", "shaker", armature.getMobilizedBodyIndex());
  c.input = makeTableProgram(*sh.program);
  const int coordinate = model.getNumCoordinates();
  model.addCoordinate(c);
  const SimTK::Vec3 g(scene.gravity[0], scene.gravity[1], scene.gravity[2]);
  model.addPointLoad({armature.getMobilizedBodyIndex(), SimTK::Vec3(0), -m * g});  // the suspension carries its weight

  Closure stinger;
  stinger.name = "shaker.stinger";
  stinger.where = scene.positions.where("shaker.at");
  stinger.mobod_a = piece;
  stinger.station_a = station_B;
  stinger.to_ground = false;
  stinger.mobod_b = armature.getMobilizedBodyIndex();
  stinger.station_b = SimTK::Vec3(0);
  stinger.directions = {SimTK::Vec3(d)};
  stinger.fit_coordinate = coordinate;
  // Between mesh nodes the stinger holds the station the linear models drive (the beam's
  // Hermite interpolation), not the chord's point of the piece it lies on.
  const bool at_node = std::any_of(axis->x.begin(), axis->x.end(), [&](double x) { return std::abs(x - st->x) <= 1e-12 * axis->length; });
  if (!at_node) stinger.points_a = StationPoint(model, *st).weightedPoints();
  model.addClosure(stinger);
}

}  // namespace mmv

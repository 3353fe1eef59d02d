// mjcf_export: the segment model mmvlab builds for a scene, written as MuJoCo's MJCF, so
// MuJoCo can do the same work on the same discretization (docs/benchmarks.md, "Against
// MuJoCo"). Every body keeps Simbody's mass properties and its pose in the scene's
// reference state; a hinge (a pin with its bending spring E I / h) becomes a MuJoCo hinge
// with that stiffness; a held joint welds its link (no joint), as mmvlab's modes hold it.
// Planar articles only (pins and welds); anything else is refused by name.
//
//   build/bench/mjcf_export [scene.yaml] [segments] > article.xml
#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include "sim/model/article_builder.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"

namespace {

std::string vec(const SimTK::Vec3& v) {
  char b[128];
  std::snprintf(b, sizeof b, "%.17g %.17g %.17g", v[0], v[1], v[2]);
  return b;
}

std::string quat(const SimTK::Rotation& R) {
  const SimTK::Quaternion q = R.convertRotationToQuaternion();  // w x y z, as MJCF
  char b[160];
  std::snprintf(b, sizeof b, "%.17g %.17g %.17g %.17g", q[0], q[1], q[2], q[3]);
  return b;
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string path = argc > 1 ? argv[1] : std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml";
  mmv::SceneFlags flags;
  if (argc > 2) flags.segments = std::stoi(argv[2]), flags.segments_label = "segments=" + std::string(argv[2]);
  const mmv::Scene scene = mmv::loadSceneFile(path, {}, flags);
  const auto* article = std::get_if<mmv::ArticleScene>(&scene);
  if (!article) throw std::runtime_error(path + ": not an article scene");
  const std::unique_ptr<mmv::Model> model = mmv::buildArticleModel(*article);
  if (model->isSpatial()) throw std::runtime_error("the spatial model is not exported (planar pins and welds only)");
  const SimTK::SimbodyMatterSubsystem& matter = model->getMatter();
  SimTK::State s = model->getReferenceState();
  model->getSystem().realize(s, SimTK::Stage::Position);
  std::map<int, const mmv::Coordinate*> coord;  // mobilized body -> its one coordinate
  for (const auto& c : model->getCoordinates()) {
    if (c.motion != mmv::CoordinateMotion::Rotation || c.mobilizer_q != 0 || coord.count(c.mobod))
      throw std::runtime_error("coordinate " + c.name + ": only one rotation per pin is exported");
    coord[c.mobod] = &c;
  }
  std::map<int, std::string> children;  // parent -> its children's MJCF
  for (int i = matter.getNumBodies() - 1; i >= 1; --i) {  // children before parents
    const SimTK::MobilizedBody& mb = matter.getMobilizedBody(SimTK::MobilizedBodyIndex(i));
    const int parent = mb.getParentMobilizedBody().getMobilizedBodyIndex();
    const SimTK::Transform X_PB = ~mb.getParentMobilizedBody().getBodyTransform(s) * mb.getBodyTransform(s);
    const SimTK::MassProperties mp = mb.getBody().getDefaultRigidBodyMassProperties();
    const SimTK::Vec3 c = mp.getMassCenter();
    const SimTK::Inertia Ic = mp.calcCentralInertia();
    std::ostringstream b;
    b << std::setprecision(17);
    b << "<body name=\"b" << i << "\" pos=\"" << vec(X_PB.p()) << "\" quat=\"" << quat(X_PB.R()) << "\">\n";
    if (mp.getMass() > 0) {
      // A planar motion turns every body about z alone: the inertias about x and y never
      // enter it, and a slender segment's (Simbody's, exact) sit on MuJoCo's triangle
      // inequality A + B >= C, which its compiler refuses at round-off; they are raised
      // to the largest of the three. Izz and the centre of mass are Simbody's.
      const SimTK::Mat33 I = Ic.toMat33();
      if (I(0, 2) != 0 || I(1, 2) != 0) throw std::runtime_error("body " + std::to_string(i) + ": not a planar inertia");
      // A point mass (a torquer of no rotary inertia) gets 1e-14 kg m^2, which MuJoCo needs
      // positive: 1e-8 of the lightest segment's.
      const double izz = std::max(I(2, 2), 1e-14), side = std::max({I(0, 0), I(1, 1), izz});
      char in[400];
      std::snprintf(in, sizeof in, "%.17g %.17g %.17g %.17g 0 0", side, side, izz, I(0, 1));
      b << "<inertial pos=\"" << vec(c) << "\" mass=\"" << mp.getMass() << "\" fullinertia=\"" << in << "\"/>\n";
    }
    const auto it = coord.find(i);
    const bool pin = SimTK::MobilizedBody::Pin::isInstanceOf(mb);
    if (it != coord.end() && !it->second->held) {
      if (!pin) throw std::runtime_error("coordinate " + it->second->name + ": not on a pin");
      const mmv::Coordinate& k = *it->second;
      const SimTK::Transform& X_BM = mb.getDefaultOutboardFrame();  // the pin turns about M's z
      const double q = mb.getOneQ(s, SimTK::MobilizerQIndex(0));
      b << "<joint name=\"" << k.name << "\" type=\"hinge\" pos=\"" << vec(X_BM.p()) << "\" axis=\""
        << vec(X_BM.R() * SimTK::Vec3(0, 0, 1)) << "\" ref=\"" << q << "\" springref=\"" << k.reference << "\" stiffness=\""
        << k.stiffness << "\"/>\n";
    } else if (!pin && !SimTK::MobilizedBody::Weld::isInstanceOf(mb)) {
      throw std::runtime_error("body " + std::to_string(i) + ": a mobilizer other than a pin or a weld");
    }
    for (const auto& p : model->getPoints())  // named points (tips, hinges) as sites
      if (p.mobod == i) b << "<site name=\"" << p.name << "\" pos=\"" << vec(p.station_B) << "\"/>\n";
    b << children[i] << "</body>\n";
    children[parent] += b.str();
  }
  const SimTK::Vec3 g = model->getGravity();
  std::cout << "<mujoco model=\"" << article->name << "\">\n"
            << "<compiler angle=\"radian\" boundmass=\"1e-12\" boundinertia=\"1e-15\"/>\n"
            << "<option gravity=\"" << vec(g) << "\"/>\n<worldbody>\n"
            << children[0] << "</worldbody>\n</mujoco>\n";
  return 0;
} catch (const std::exception& e) {
  std::cerr << "mjcf_export: " << e.what() << "\n";
  return 1;
}

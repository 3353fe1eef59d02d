#include "sim/view/hamsas_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {

const std::map<std::string, std::array<float, 4>>& groupColors() {
  static const std::map<std::string, std::array<float, 4>> colors{
      {"ot", {0.0f, 0.45f, 0.70f, 1}},     {"sb", {0.90f, 0.62f, 0.0f, 1}}, {"ip_leg", {0.0f, 0.62f, 0.45f, 1}},
      {"lp", {0.80f, 0.47f, 0.65f, 1}},    {"base", {0.55f, 0.55f, 0.5f, 1}}};
  return colors;
}

const char* groupName(const std::string& g) {
  if (g == "ot") return "optical table";
  if (g == "sb") return "spring box";
  if (g == "ip_leg") return "IP legs with counterweights";
  if (g == "lp") return "little pendulums";
  return "base (prescribed motion)";
}

/// The sensors (relative displacement, spring box to base): a cube and a rod along the
/// direction each measures, labelled.
void addSensors(DrawList& d, const SpatialSpec& s) {
  for (const auto& sensor : s.sensors) {
    DrawItem cube;
    cube.rgba = {0.8f, 0.1f, 0.1f, 1};
    cube.size = Eigen::Vector3d::Constant(0.04);
    cube.pose.translation() = sensor.point;
    d.items.push_back(cube);
    DrawItem rod;
    rod.shape = DrawItem::Shape::Cylinder;
    rod.rgba = {0.45f, 0.0f, 0.0f, 1};
    rod.size = {0.16, 0.008, 0.008};
    rod.pose = poseAlong(sensor.point + 0.08 * sensor.direction.normalized(), sensor.direction);
    d.items.push_back(rod);
    d.labels.push_back({sensor.point, sensor.name, {0.8f, 0.1f, 0.1f, 1}});
  }
}

}  // namespace

namespace {

/// The bodies, each moved by motion[b] (translation, small rotation; m, rad, world) over
/// a translucent ghost when `motion` is given, coloured by the drawn translation.
void addBodies(DrawList& d, const SpatialSpec& s, const Eigen::AlignedBox3d& extent, const std::vector<BodyMotion>* motion) {
  std::map<std::string, bool> seen;
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const SpatialBody& body = s.bodies[b];
    DrawItem it;
    it.rgba = groupColors().count(body.group) ? groupColors().at(body.group) : groupColors().at("base");
    if (body.group == "ot") it.rgba[3] = 0.55f;  // the table would hide the spring box and the legs
    it.size = b == 0 ? Eigen::Vector3d(1.6, 1.6, 0.05) : equivalentBox(body);
    it.pose.translation() = b == 0 ? Eigen::Vector3d(body.com.x(), body.com.y(), extent.min().z() - 0.1) : body.com;
    if (motion) {
      if (b > 0) {
        DrawItem ghost = it;
        ghost.rgba = {0.6f, 0.6f, 0.6f, 0.25f};
        d.items.push_back(ghost);
      }
      const Eigen::Vector3d t = (*motion)[b].head<3>(), w = (*motion)[b].tail<3>();
      it.pose.translation() += t;
      if (w.norm() > 0) it.pose.linear() = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix();
      if (b > 0) it.value = t.norm();
    }
    d.items.push_back(it);
    if (!seen[body.group]) {
      d.legend.push_back({groupName(body.group), it.rgba});
      seen[body.group] = true;
    }
  }
}

/// The springs' and joints' points, and the sensors.
void addPoints(DrawList& d, const SpatialSpec& s) {
  for (const auto& sp : s.springs) {
    DrawItem it;
    it.shape = DrawItem::Shape::Sphere;
    it.size = Eigen::Vector3d::Constant(sp.joint ? 0.03 : 0.06);
    it.rgba = sp.joint ? std::array<float, 4>{0.3f, 0.3f, 0.3f, 1} : std::array<float, 4>{0.84f, 0.37f, 0.0f, 1};
    it.pose.translation() = sp.point;
    d.items.push_back(it);
  }
  d.legend.push_back({"MGAS springs", {0.84f, 0.37f, 0.0f, 1}});
  d.legend.push_back({"effective spherical joints", {0.3f, 0.3f, 0.3f, 1}});
  addSensors(d, s);
  if (!s.sensors.empty()) d.legend.push_back({"sensors (rod: measuring axis)", {0.8f, 0.1f, 0.1f, 1}});
}

}  // namespace

DrawList drawHamsas(const HamsasScene& scene, const HamsasModes& h, std::optional<ModeNumber> shown, double phase,
                    double scale, bool short_title) {
  const int mode = shown ? shown->index() : -1;  // -1: at rest
  const SpatialSpec& s = h.model;
  DrawList d;
  d.up = Eigen::Vector3d::UnitZ();
  Eigen::VectorXd phi;
  double k = 0, peak = 0;
  Eigen::AlignedBox3d extent;
  for (const auto& b : s.bodies) extent.extend(b.com);
  std::vector<BodyMotion> motion;
  if (mode >= 0) {
    MMV_DEMAND(mode < h.solution.shapes.cols());
    phi = h.solution.shapes.col(mode);
    // The largest displacement of a body's corner: its translation plus its rotation
    // times its half-diagonal.
    for (std::size_t b = 1; b < s.bodies.size(); ++b) {
      const int r = SpatialLinearization::row(static_cast<int>(b));
      peak = std::max(peak, phi.segment<3>(r).norm() + phi.segment<3>(r + 3).norm() * 0.5 * equivalentBox(s.bodies[b]).norm());
    }
    k = scale > 0 ? scale : (peak > 0 ? 0.1 * std::max(extent.diagonal().norm(), 0.5) / peak : 1.0);
    motion.assign(s.bodies.size(), BodyMotion::Zero());
    for (std::size_t b = 1; b < s.bodies.size(); ++b)
      motion[b] = phase * k * phi.segment<6>(SpatialLinearization::row(static_cast<int>(b)));
  }
  addBodies(d, s, extent, mode >= 0 ? &motion : nullptr);
  addPoints(d, s);
  char title[256];
  if (mode < 0) {
    std::snprintf(title, sizeof title, "%s: %zu bodies at the design configuration", scene.name.c_str(), s.bodies.size());
  } else {
    d.has_color_bar = true;
    d.color_bar = {"|u| (m, drawn shape)", 0.0, k * peak};
    d.legend.push_back({"design configuration (ghost)", {0.6f, 0.6f, 0.6f, 1}});
    if (short_title)
      std::snprintf(title, sizeof title, "mode %d: %.4g Hz, %s", shown->number(), h.modes[mode].frequency_hz,
                    h.modes[mode].label.c_str());
    else
      std::snprintf(title, sizeof title, "%s: mode %d, %.4g Hz (%s), shape x %.3g", scene.name.c_str(), shown->number(),
                    h.modes[mode].frequency_hz, h.modes[mode].label.c_str(), k);
  }
  d.title = title;
  return d;
}

DrawList drawHamsasMoved(const HamsasScene& scene, const HamsasModes& h, const std::vector<BodyMotion>& motion, double scale,
                         const std::string& title) {
  const SpatialSpec& s = h.model;
  MMV_DEMAND(motion.size() == s.bodies.size());
  DrawList d;
  d.up = Eigen::Vector3d::UnitZ();
  Eigen::AlignedBox3d extent;
  for (const auto& b : s.bodies) extent.extend(b.com);
  std::vector<BodyMotion> drawn(motion.size());
  double peak = 0;
  for (std::size_t b = 0; b < motion.size(); ++b) {
    drawn[b] = scale * motion[b];
    if (b > 0) peak = std::max(peak, motion[b].head<3>().norm());
  }
  addBodies(d, s, extent, &drawn);
  addPoints(d, s);
  d.has_color_bar = true;
  d.color_bar = {strf("|u| (m, drawn: motion x %.3g)", scale), 0.0, std::max(scale * peak, 1e-12)};
  d.legend.push_back({"design configuration (ghost)", {0.6f, 0.6f, 0.6f, 1}});
  d.title = scene.name + ": " + title;
  return d;
}

}  // namespace mmv

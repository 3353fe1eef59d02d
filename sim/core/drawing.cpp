#include "sim/core/drawing.hpp"

#include <cmath>

namespace mmv {

Eigen::AlignedBox3d DrawList::bounds() const {
  Eigen::AlignedBox3d box;
  for (const auto& it : items) {
    const double r = 0.5 * it.size.maxCoeff();
    box.extend(it.pose.translation() + Eigen::Vector3d::Constant(r));
    box.extend(it.pose.translation() - Eigen::Vector3d::Constant(r));
  }
  for (const auto& l : labels) box.extend(l.at);
  if (box.isEmpty()) box.extend(Eigen::Vector3d::Zero());
  return box;
}

bool presetCamera(const std::string& name, const Eigen::AlignedBox3d& bounds, Camera& c, const Eigen::Vector3d& up) {
  // Directions for +y up, then turned so that +y becomes `up` (+z up: x stays, y -> z, z -> -y).
  Eigen::Vector3d dir, cam_up = Eigen::Vector3d::UnitY();
  if (name == "front") dir = Eigen::Vector3d(0, 0, 1);
  else if (name == "side") dir = Eigen::Vector3d(1, 0, 0);
  else if (name == "top") dir = Eigen::Vector3d(0, 1, 0), cam_up = Eigen::Vector3d(0, 0, -1);
  else if (name == "iso") dir = Eigen::Vector3d(0.6, 0.45, 0.66).normalized();
  else return false;
  if (up.z() > 0.5) {
    auto turn = [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), -v.z(), v.y()); };
    dir = turn(dir);
    cam_up = turn(cam_up);
  }
  c.up = cam_up;
  c.target = bounds.center();
  const double radius = std::max(0.5 * bounds.diagonal().norm(), 0.05);
  const double half = 0.5 * c.fov_deg * M_PI / 180;
  c.eye = c.target + dir * (1.15 * radius / std::sin(half));
  return true;
}

}  // namespace mmv

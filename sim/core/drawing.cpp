#include "sim/core/drawing.hpp"

#include <cmath>

namespace mmv {

Eigen::AlignedBox3d DrawList::bounds(bool with_context) const {
  Eigen::AlignedBox3d box;
  for (const auto& it : items) {
    if (it.context && !with_context) continue;
    Eigen::Vector3d half = 0.5 * it.size;
    if (it.shape == DrawItem::Shape::Sphere) half.setConstant(0.5 * it.size.x());
    if (it.shape == DrawItem::Shape::Cylinder) half.z() = half.y();
    const Eigen::Vector3d extent = it.pose.linear().cwiseAbs() * half;  // the rotated box's half-extent
    box.extend(it.pose.translation() + extent);
    box.extend(it.pose.translation() - extent);
  }
  for (const auto& l : labels)
    if (with_context || !l.context) box.extend(l.at);
  if (box.isEmpty()) box.extend(Eigen::Vector3d::Zero());
  return box;
}

bool DrawList::hasContext() const {
  for (const auto& it : items)
    if (it.context) return true;
  return false;
}

Eigen::Isometry3d poseAlong(const Eigen::Vector3d& centre, const Eigen::Vector3d& dir) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d x = dir.normalized();
  Eigen::Vector3d z = Eigen::Vector3d::UnitZ() - x.z() * x;
  if (z.norm() < 1e-9) z = Eigen::Vector3d::UnitY();
  z.normalize();
  T.linear().col(0) = x;
  T.linear().col(1) = z.cross(x);
  T.linear().col(2) = z;
  T.translation() = centre;
  return T;
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

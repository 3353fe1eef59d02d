#include "sim/core/drawing.hpp"

#include <cmath>
#include <vector>

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

bool presetCamera(const std::string& name, const Eigen::AlignedBox3d& bounds, Camera& c, const Eigen::Vector3d& up,
                  const ViewWindow& window) {
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
  c.fit_preset = name;
  c.fit_bounds = bounds;
  c.fit_up = up;
  // Camera axes: s to the right, u up the picture, dir toward the camera.
  const Eigen::Vector3d s = (-dir).cross(cam_up).normalized(), u = s.cross(-dir);
  const double tan_v = std::tan(0.5 * c.fov_deg * M_PI / 180), tan_h = tan_v * window.aspect;
  const double hx = 0.45 * (window.x1 - window.x0), hy = 0.45 * (window.y1 - window.y0);  // 90 % of the window
  const double cx = 0.5 * (window.x0 + window.x1), cy = 0.5 * (window.y0 + window.y1);
  const Eigen::Vector3d centre = bounds.center();
  std::vector<Eigen::Vector3d> corners;  // from the centre
  for (int k = 0; k < 8; ++k)
    corners.push_back(bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(k)) - centre);
  // The distance at which every corner's |offset| / depth fits the window's half-size
  // (centred), then grown until the shifted picture keeps every corner inside.
  double D = 0.05 / tan_v;
  for (const auto& p : corners)
    D = std::max({D, p.dot(dir) + std::abs(p.dot(s)) / (hx * tan_h), p.dot(dir) + std::abs(p.dot(u)) / (hy * tan_v)});
  for (int pass = 0; pass < 60; ++pass) {
    const Eigen::Vector3d shift = -s * (cx * D * tan_h) - u * (cy * D * tan_v);  // the box's centre to (cx, cy)
    bool inside = true;
    for (const auto& p : corners) {
      const double depth = D - p.dot(dir);
      const double x = (p - shift).dot(s) / (depth * tan_h), y = (p - shift).dot(u) / (depth * tan_v);
      inside = inside && depth > 0 && x >= window.x0 && x <= window.x1 && y >= window.y0 && y <= window.y1;
    }
    c.target = centre + shift;
    c.eye = c.target + dir * D;
    if (inside) break;
    D *= 1.05;
  }
  return true;
}

}  // namespace mmv

#include "sim/view/facility_drawing.hpp"

#include <cmath>

#include "sim/core/text.hpp"

namespace mmv {
namespace {

const std::array<float, 4> kTable{0.55f, 0.55f, 0.5f, 1}, kGimbal{0.45f, 0.45f, 0.52f, 1},
    kFloor{0.78f, 0.76f, 0.70f, 1}, kPlatform{0.60f, 0.60f, 0.62f, 0.4f}, kCeiling{0.75f, 0.78f, 0.85f, 0.12f};

DrawItem box(const Eigen::Vector3d& centre, const Eigen::Vector3d& size, const std::array<float, 4>& rgba) {
  DrawItem it;
  it.size = size;
  it.rgba = rgba;
  it.pose.translation() = centre;
  return it;
}

DrawItem cylinder(const Eigen::Vector3d& centre, const Eigen::Vector3d& axis, double length, double diameter,
                  const std::array<float, 4>& rgba) {
  DrawItem it;
  it.shape = DrawItem::Shape::Cylinder;
  it.size = {length, diameter, diameter};
  it.rgba = rgba;
  it.pose = poseAlong(centre, axis);
  return it;
}

/// The platform: four slabs around the square hole centred on the base.
void addPlatform(DrawList& d, const facility::LabSpec& lab, const Eigen::Vector3d& base, double top) {
  const double L = lab.platform_length, W = lab.platform_width, h = lab.hole_side, t = lab.platform_thickness;
  const double y = top - 0.5 * t;
  for (int side : {-1, 1}) {
    const Eigen::Vector3d centre(base.x(), y, base.z());
    d.items.push_back(box(centre + Eigen::Vector3d(side * 0.25 * (L + h), 0, 0), {0.5 * (L - h), t, W}, kPlatform));
    d.items.push_back(box(centre + Eigen::Vector3d(0, 0, side * 0.25 * (W + h)), {h, t, 0.5 * (W - h)}, kPlatform));
  }
}

void addLab(DrawList& d, const facility::LabSpec& lab, const Eigen::Vector3d& base) {
  const std::size_t first_item = d.items.size(), first_label = d.labels.size();
  const facility::LabLevels y = facility::labLevels(lab, base.y());
  auto at = [&](double height) { return Eigen::Vector3d(base.x(), height, base.z()); };
  d.items.push_back(box(at(y.floor - 0.05), {lab.floor_length, 0.1, lab.floor_width}, kFloor));
  d.items.back().room = true;
  addPlatform(d, lab, base, y.platform_top);
  d.items.push_back(box(at(y.ceiling + 0.05), {lab.floor_length, 0.1, lab.floor_width}, kCeiling));
  d.items.back().room = true;
  const Eigen::Vector3d edge(0.5 * lab.platform_length, 0, 0.5 * lab.platform_width);
  d.labels.push_back({at(y.platform_top) + edge,
                      strf("platform top %.2f m above the floor, hole %.2f m square", lab.platform_height, lab.hole_side),
                      {0.2f, 0.2f, 0.2f, 1}});
  d.labels.push_back({at(y.floor) + Eigen::Vector3d(0.5 * lab.floor_length, 0, 0.5 * lab.floor_width),
                      strf("floor %.1f m x %.1f m", lab.floor_length, lab.floor_width), {0.2f, 0.2f, 0.2f, 1}});
  d.labels.back().room = true;
  d.labels.push_back({at(y.ceiling) + Eigen::Vector3d(0.5 * lab.floor_length, 0, 0.5 * lab.floor_width),
                      strf("ceiling %.1f m", lab.ceiling_height), {0.2f, 0.2f, 0.2f, 1}});
  d.labels.back().room = true;
  d.legend.push_back({"lab: platform and its hole (floor and ceiling: --view lab)", kFloor});
  for (std::size_t i = first_item; i < d.items.size(); ++i) d.items[i].context = true;
  for (std::size_t i = first_label; i < d.labels.size(); ++i) d.labels[i].context = true;
}

}  // namespace

double mountHeight(const ArticleScene& scene) { return scene.lab ? scene.lab->base_below_platform : 0.6; }

void addFacility(DrawList& d, const ArticleScene& scene, const Eigen::Vector3d& moved) {
  const BaseSpec& b = scene.article.base;
  const Eigen::Vector3d still(b.position[0], b.position[1], b.position[2]), base = still + moved;
  const double top = mountHeight(scene);  // the table's underside, above the base joint
  const bool table = b.type == BaseType::Table;
  if (table) {
    d.items.push_back(box(base + Eigen::Vector3d(0, top + 0.05, 0), {1.0, 0.1, 1.0}, kTable));
    d.legend.push_back({"base excitation table (schematic)", kTable});
  }
  double hang = top;  // where the post from the base ends
  if (b.gimbal) {
    // Payload plate at the base joint; rings centred halfway up the stack, the
    // largest fitting it, about yaw (y), pitch (z) and roll (x).
    const double dia = std::min(0.5, 0.9 * top);
    d.items.push_back(box(base + Eigen::Vector3d(0, 0.015, 0), {0.7 * dia, 0.03, 0.7 * dia}, kGimbal));
    const Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
    for (int k = 0; k < 3; ++k)
      d.items.push_back(cylinder(base + Eigen::Vector3d(0, 0.5 * top, 0), axes[k], 0.02, dia * (1 - 0.16 * k),
                                 {kGimbal[0], kGimbal[1], kGimbal[2], 0.6f}));
    d.legend.push_back({"gimbal: payload plate, yaw, pitch and roll rings (schematic)", kGimbal});
    const double rings_top = 0.5 * (top + dia);  // a hanger from the rings to the table or platform
    if (top > rings_top)
      d.items.push_back(cylinder(base + Eigen::Vector3d(0, 0.5 * (rings_top + top), 0), Eigen::Vector3d::UnitY(),
                                 top - rings_top, 0.05, kGimbal));
    hang = 0;  // the rings carry it
  }
  if ((table || scene.lab) && hang > 0)
    d.items.push_back(cylinder(base + Eigen::Vector3d(0, 0.5 * hang, 0), Eigen::Vector3d::UnitY(), hang, 0.06, kTable));
  if (scene.lab) addLab(d, *scene.lab, still);
}

}  // namespace mmv

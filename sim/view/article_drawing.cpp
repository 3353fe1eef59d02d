#include "sim/view/article_drawing.hpp"

#include "sim/core/text.hpp"

#include "sim/modes/planarity.hpp"

#include <algorithm>
#include <cmath>

#include "article/section.hpp"
#include "sim/core/errors.hpp"
#include "sim/view/facility_drawing.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/planarity.hpp"

namespace mmv {
namespace {

constexpr double kSteel = 7850;  ///< kg/m^3: how big a lumped mass is drawn.
constexpr double kMinSection = 0.015;  ///< m: thinner sections are drawn this thick (link 3's 2.5 mm rods would vanish).
const std::array<std::array<float, 4>, 7> kPalette{{{0.90f, 0.62f, 0.0f, 1}, {0.34f, 0.71f, 0.91f, 1}, {0.0f, 0.62f, 0.45f, 1},
                                                    {0.0f, 0.45f, 0.70f, 1}, {0.84f, 0.37f, 0.0f, 1}, {0.80f, 0.47f, 0.65f, 1},
                                                    {0.94f, 0.89f, 0.26f, 1}}};
const std::array<float, 4> kTorquer{0.35f, 0.35f, 0.38f, 1}, kSensor{0.80f, 0.10f, 0.10f, 1}, kFixture{0.55f, 0.55f, 0.5f, 1};
/// Gravity's arrow.
const std::array<float, 4> kGravity{0.25f, 0.25f, 0.25f, 1};
/// A placement's proposed sensors: blue, apart from the scene's own (red).
const std::array<float, 4> kProposed{0.05f, 0.30f, 0.70f, 1};
const std::array<float, 4> kShaker{0.20f, 0.30f, 0.40f, 1};

Eigen::Vector3d vec(const SimTK::Vec3& v) { return {v[0], v[1], v[2]}; }

/// The cross-section as drawn: shape and size (height in the plane, width out of it),
/// at least kMinSection so that every link shows.
void sectionShape(const Section& s, DrawItem& item, double length) {
  switch (s.shape) {
    case SectionShape::RoundRod:
      item.shape = DrawItem::Shape::Cylinder;
      item.size = {length, 2 * s.radius, 2 * s.radius};
      break;
    case SectionShape::Rectangle:
    case SectionShape::RectangularTube: item.size = {length, s.h, s.b}; break;
    case SectionShape::Explicit: {
      const double side = std::sqrt(s.explicit_area);
      item.size = {length, side, side};
      break;
    }
  }
  item.size.y() = std::max(item.size.y(), kMinSection);
  item.size.z() = std::max(item.size.z(), kMinSection);
}

/// Centreline samples of a link: 8 per segment (at least 16), root to tip.
std::vector<StationPoint> samples(const Model& model, const LinkSpec& l) {
  const int n = std::clamp(8 * (l.rigid ? 1 : l.segments), 16, 400);
  std::vector<StationPoint> out;
  for (int i = 0; i <= n; ++i) out.emplace_back(model, StationSpec{"", l.name, l.length * i / n, 0.0});
  return out;
}

/// One link as boxes (or cylinders) between consecutive centreline points; `values`
/// (one per point, may be empty) colour the segments through the colour bar.
void addLink(DrawList& d, const ArticleSpec& a, const LinkSpec& l, const std::vector<Eigen::Vector3d>& pts,
             const std::array<float, 4>& rgba, const std::vector<double>& values) {
  const Section& sec = *a.findSection(l.section);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    DrawItem it;
    it.rgba = rgba;
    it.pose = poseAlong(0.5 * (pts[i] + pts[i + 1]), pts[i + 1] - pts[i]);
    sectionShape(sec, it, (pts[i + 1] - pts[i]).norm() * 1.02);  // a little overlap closes the joints between segments
    if (!values.empty()) it.value = 0.5 * (values[i] + values[i + 1]);
    d.items.push_back(it);
  }
}

std::vector<Eigen::Vector3d> positions(const std::vector<StationPoint>& pts, const SimTK::State& s) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : pts) out.push_back(vec(p.position(s)));
  return out;
}

/// A lumped mass's least drawn size, m: joint 3's 88 g torquer as steel is 24 mm across,
/// lost at the article's scale (issue 36: "torquer 3 invisible").
constexpr double kMinLumpedSize = 0.06;

/// A cylinder about world z (torquers, encoders) or a sphere, of steel of `mass`, at least
/// kMinLumpedSize across.
DrawItem lumped(const Eigen::Vector3d& at, double mass, bool sphere) {
  DrawItem it;
  it.rgba = kTorquer;
  const double volume = mass / kSteel;
  if (sphere) {
    it.shape = DrawItem::Shape::Sphere;
    it.size = Eigen::Vector3d::Constant(std::max(kMinLumpedSize, std::cbrt(6 * volume / M_PI)));
  } else {
    it.shape = DrawItem::Shape::Cylinder;
    const double dia = std::max(kMinLumpedSize, std::cbrt(4 * volume / M_PI));  // length = diameter
    it.size = {dia, dia, dia};
  }
  it.pose = poseAlong(at, Eigen::Vector3d::UnitZ());
  return it;
}

void addHardware(DrawList& d, const ArticleScene& scene, const Model& model, const SimTK::State& s) {
  const ArticleSpec& a = scene.article;
  for (const auto& j : a.joints) {
    const NamedPoint* p = model.findPoint(j.name);
    if (p && j.torquer) d.items.push_back(lumped(vec(model.findPointLocation(s, *p)), j.torquer->mass, false));
  }
  for (const auto& l : a.links)
    if (l.tip_mass) d.items.push_back(lumped(vec(model.findPointLocation(s, *model.findPoint(l.name + ".tip"))), l.tip_mass->mass, true));
  for (const auto& c : a.closures) {
    DrawItem it;
    it.shape = DrawItem::Shape::Sphere;
    it.rgba = kFixture;
    it.size = Eigen::Vector3d::Constant(0.05);
    it.pose.translation() = vec(model.findPointLocation(s, *model.findPoint(c.point)));
    d.items.push_back(it);
  }
  // The table (a slider along world x) carries the table and gimbal drawings.
  Eigen::Vector3d moved = Eigen::Vector3d::Zero();
  for (int i = 0; i < model.getNumCoordinates(); ++i)
    if (model.getCoordinates()[i].name == "table.x") moved.x() = s.getQ()[model.getQIndex(i)];
  addFacility(d, scene, moved);
}

/// The scene's extra shaker (`shaker:`) where the scene fixes it; at `auto` the place is
/// place-sensors' choice (its review renders draw that one).
void addShaker(DrawList& d, const ArticleScene& scene, const Model& model, const SimTK::State& s) {
  if (!scene.shaker || scene.shaker->autoAt()) return;
  std::string error;
  const auto p = PointRef::resolve(model, scene.article, scene.shaker->at, error);
  MMV_DEMAND(p.has_value());
  const auto& dir = scene.shaker->direction;
  addShakerDrawing(d, vec(p->position(s)), Eigen::Vector3d(dir[0], dir[1], dir[2]),
                   strf("shaker at %s (%.0f N)", scene.shaker->at.c_str(), scene.shaker->hardware.force_limit));
}

void addSensors(DrawList& d, const ArticleScene& scene, const Model& model, const SimTK::State& s) {
  for (const auto& sensor : scene.sensors) {
    Eigen::Vector3d at;
    DrawItem it;
    it.rgba = kSensor;
    if (sensor.type == "encoder") {
      const NamedPoint* p = model.findPoint(sensor.target);
      MMV_DEMAND(p != nullptr);
      at = vec(model.findPointLocation(s, *p));
      it.shape = DrawItem::Shape::Cylinder;
      it.size = {0.02, 0.14, 0.14};
      it.pose = poseAlong(at + Eigen::Vector3d(0, 0, 0.08), Eigen::Vector3d::UnitZ());
    } else {
      std::string error;
      const auto p = PointRef::resolve(model, scene.article, sensor.target, error);
      MMV_DEMAND(p.has_value());
      at = vec(p->position(s));
      it.shape = sensor.type == "rate_gyro" ? DrawItem::Shape::Cylinder : DrawItem::Shape::Box;
      it.size = Eigen::Vector3d::Constant(0.04);
      it.pose = poseAlong(at + Eigen::Vector3d(0, 0, 0.03), vec(p->localAxis(s, 0)));
    }
    d.items.push_back(it);
    d.labels.push_back({at, sensor.name + " (" + sensor.type + ")", kSensor});
    // Its measuring axis: an accelerometer's along or across its link; a gyro's its
    // rotation axis (out of the plane of motion unless the spatial model's scene picks
    // another); an encoder's its joint's, out of the plane.
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    if (sensor.type != "encoder") {
      std::string error;
      axis = vec(PointRef::resolve(model, scene.article, sensor.target, error)->localAxis(s, sensor.axis));
    }
    DrawItem arrow;
    arrow.shape = DrawItem::Shape::Cylinder;
    arrow.rgba = {0.45f, 0.0f, 0.0f, 1};
    arrow.size = {0.16, 0.008, 0.008};
    arrow.pose = poseAlong(it.pose.translation() + 0.08 * axis, axis);
    d.items.push_back(arrow);
  }
  if (!scene.sensors.empty()) d.legend.push_back({"the scene's sensors (rod: measuring axis)", kSensor});
}

}  // namespace

void addShakerDrawing(DrawList& d, const Eigen::Vector3d& at, const Eigen::Vector3d& direction, const std::string& label) {
  const Eigen::Vector3d dir = direction.normalized();
  constexpr double kStinger = 0.25, kBody = 0.2;  // m: the stinger's length, the shaker's (schematic)
  DrawItem stinger;
  stinger.shape = DrawItem::Shape::Cylinder;
  stinger.rgba = kShaker;
  stinger.size = {kStinger, 0.012, 0.012};
  stinger.pose = poseAlong(at - 0.5 * kStinger * dir, dir);
  d.items.push_back(stinger);
  DrawItem body = stinger;
  body.size = {kBody, 0.16, 0.16};
  body.pose = poseAlong(at - (kStinger + 0.5 * kBody) * dir, dir);
  d.items.push_back(body);
  d.labels.push_back({at - (kStinger + kBody) * dir, label, kShaker});
  d.legend.push_back({"shaker and stinger (schematic; it pushes along the stinger)", kShaker});
}

void addProposedSensors(DrawList& d, const std::vector<Eigen::Vector3d>& at, const std::vector<std::string>& names,
                        const std::vector<std::vector<Eigen::Vector3d>>& axes, const std::vector<double>& values,
                        const std::string& legend) {
  MMV_DEMAND(at.size() == names.size() && (values.empty() || values.size() == at.size()) &&
             (axes.empty() || axes.size() == at.size()));
  for (std::size_t i = 0; i < at.size(); ++i) {
    DrawItem it;
    it.rgba = kProposed;
    it.size = Eigen::Vector3d::Constant(0.06);
    it.pose.translation() = at[i] + Eigen::Vector3d(0, 0, 0.04);
    if (!values.empty()) it.value = values[i];
    d.items.push_back(it);
    if (!names[i].empty()) d.labels.push_back({at[i], names[i], kProposed});
    for (std::size_t k = 0; i < axes.size() && k < axes[i].size(); ++k) {  // a rod along each measuring direction
      DrawItem rod;
      rod.shape = DrawItem::Shape::Cylinder;
      rod.rgba = kProposed;
      rod.size = {0.2, 0.01, 0.01};
      rod.pose = poseAlong(it.pose.translation() + 0.1 * axes[i][k], axes[i][k]);
      d.items.push_back(rod);
    }
  }
  if (!legend.empty() && !at.empty()) d.legend.push_back({legend, kProposed});
}

/// Which way gravity points, as an arrow beside the links drawn so far (a fifth of their
/// extent long), and the fixed mount of an article on no table or gimbal: a plate behind
/// the base joints (issue 36: a drawing without either left the reader to guess).
void addGravityAndMount(DrawList& d, const ArticleScene& scene) {
  const Eigen::AlignedBox3d box = d.bounds();
  const double size = std::max(0.2, box.sizes().head<2>().maxCoeff());
  const Eigen::Vector3d g(scene.gravity[0], scene.gravity[1], scene.gravity[2]);
  if (g.norm() > 0 && !box.isEmpty()) {
    const Eigen::Vector3d dir = g.normalized(), start(box.max().x() + 0.12 * size, box.max().y() - 0.05 * size, 0);
    DrawItem shaft;
    shaft.shape = DrawItem::Shape::Cylinder;
    shaft.rgba = kGravity;
    shaft.size = {0.2 * size, 0.012 * size, 0.012 * size};
    shaft.pose = poseAlong(start + 0.1 * size * dir, dir);
    d.items.push_back(shaft);
    DrawItem head = shaft;  // a short thick piece at the end: the arrow's head
    head.size = {0.04 * size, 0.035 * size, 0.035 * size};
    head.pose = poseAlong(start + 0.2 * size * dir, dir);
    d.items.push_back(head);
    d.labels.push_back({start + 0.1 * size * dir, strf("gravity %.3g m/s^2", g.norm()), kGravity});  // beside the shaft
  }
  const BaseSpec& base = scene.article.base;
  if (base.type == BaseType::Fixed && !base.gimbal) {
    const Eigen::Vector3d at(base.position[0], base.position[1], base.position[2]);
    const Eigen::Vector3d out(std::cos(base.direction), std::sin(base.direction), 0);  // the joints' zero direction
    DrawItem plate;
    plate.rgba = kFixture;
    plate.size = {0.03 * size, 0.12 * size, 0.12 * size};
    plate.pose = poseAlong(at - 0.02 * size * out, out);
    d.items.push_back(plate);
    d.legend.push_back({"fixed mount", kFixture});
  }
}

DrawList drawArticle(const ArticleScene& scene, const Model& model, const SimTK::State& s) {
  DrawList d;
  d.title = scene.name;
  for (std::size_t k = 0; k < scene.article.links.size(); ++k) {
    const LinkSpec& l = scene.article.links[k];
    const auto& color = kPalette[k % kPalette.size()];
    addLink(d, scene.article, l, positions(samples(model, l), s), color, {});
    d.legend.push_back({l.name, color});
  }
  addGravityAndMount(d, scene);
  d.legend.push_back({"torquers, tip masses (as steel of their mass, at least 60 mm)", kTorquer});
  d.legend.push_back({"sections drawn true to size, at least 15 mm", {1, 1, 1, 1}});
  addHardware(d, scene, model, s);
  addShaker(d, scene, model, s);
  addSensors(d, scene, model, s);
  return d;
}

ModeFrames::ModeFrames(const ArticleScene& scene, const SolvedScene& solved, ModeNumber mode, double scale)
    : scene_(scene), solved_(solved), mode_(mode) {
  const Model& model = *solved.model;
  MMV_DEMAND(mode.index() >= 0 && mode.index() < solved.modes.omega2.size());
  SimTK::State eq = solved.equilibrium.state;
  model.getSystem().realize(eq, SimTK::Stage::Position);
  const Eigen::VectorXd phi = solved.modes.shapes.col(mode.index());
  const std::vector<int>& dofs = solved.linearized.dofs;
  // The shape as the linear model has it: every centreline point displaced by its
  // translation per unit modal coordinate (the stations' Jacobians times phi), scaled
  // so the largest is 10 % of the article's extent unless a scale is given.
  double peak = 0, extent = 0;
  for (const auto& l : scene.article.links) {
    const std::vector<StationPoint> pts = samples(model, l);
    rest_.push_back(positions(pts, eq));
    shape_.emplace_back();
    const int rows = model.isSpatial() ? 3 : 2;  // the spatial model's shapes leave the plane
    for (const auto& p : pts) {
      const Eigen::VectorXd u = p.translationJacobian(eq, dofs, rows) * phi;
      shape_.back().push_back(Eigen::Vector3d(u[0], u[1], rows == 3 ? u[2] : 0.0));
      peak = std::max(peak, u.norm());
    }
    extent += l.length;
  }
  dominant_ = dominantStrainLink(model, dofs, phi);
  if (model.isSpatial()) dominant_ += ", " + classifyMode(model, dofs, phi).label;
  // The link that moves most (a swing of link 3 whose strain is in link 1, issue 36).
  double widest = -1, turn = 0;  // turn: the largest |du| / |dx| between neighbouring points
  for (std::size_t j = 0; j < shape_.size(); ++j)
    for (std::size_t i = 0; i < shape_[j].size(); ++i) {
      if (shape_[j][i].norm() > widest) widest = shape_[j][i].norm(), moving_ = scene.article.links[j].name;
      if (i > 0)
        if (const double dx = (rest_[j][i] - rest_[j][i - 1]).norm(); dx > 1e-9) turn = std::max(turn, (shape_[j][i] - shape_[j][i - 1]).norm() / dx);
    }
  // Drawn so the largest translation is 10 % of the article's length, but no piece turns
  // by more than about 0.3 rad: a linear shape drawn larger visibly lengthens its links (4 %).
  double automatic = peak > 0 ? 0.1 * extent / peak : 1.0;
  if (turn > 0) automatic = std::min(automatic, 0.3 / turn);
  scale_ = scale > 0 ? scale : automatic;
  peak_ = scale_ * peak;
  addHardware(hardware_, scene, model, eq);
}

DrawList ModeFrames::frame(double phase, bool short_title) const {
  DrawList d = hardware_;
  for (std::size_t j = 0; j < scene_.article.links.size(); ++j) {
    std::vector<Eigen::Vector3d> moved;
    std::vector<double> values;
    for (std::size_t i = 0; i < rest_[j].size(); ++i) {
      moved.push_back(rest_[j][i] + phase * scale_ * shape_[j][i]);
      values.push_back(peak_ > 0 ? std::abs(phase) * scale_ * shape_[j][i].norm() / peak_ : 0.0);
    }
    addLink(d, scene_.article, scene_.article.links[j], moved, {1, 1, 1, 1}, values);
    addLink(d, scene_.article, scene_.article.links[j], rest_[j], {0.6f, 0.6f, 0.6f, 0.25f}, {});  // ghost
  }
  d.has_color_bar = true;
  d.color_bar = {"|u| / largest (drawn shape)", 0.0, 1.0};  // a mode shape has no size: the colours compare its points
  d.legend.push_back({"equilibrium (ghost)", {0.6f, 0.6f, 0.6f, 1}});
  char title[320];
  const double hz = solved_.modes.frequencyHz(mode_.index());
  const std::string where = moving_ == dominant_ ? "in " + dominant_ : "strain in " + dominant_ + ", moves " + moving_;
  if (short_title)
    std::snprintf(title, sizeof title, "mode %d: %.4g Hz, %s", mode_.number(), hz, where.c_str());
  else
    std::snprintf(title, sizeof title, "%s: mode %d, %.4g Hz, most strain in %s, largest motion in %s; drawn %.3g m at its largest",
                  scene_.name.c_str(), mode_.number(), hz, dominant_.c_str(), moving_.c_str(), peak_);
  d.title = title;
  return d;
}

DrawList drawMode(const ArticleScene& scene, const SolvedScene& solved, ModeNumber mode, double phase, double scale,
                  double* used_scale, bool short_title) {
  const ModeFrames frames(scene, solved, mode, scale);
  if (used_scale) *used_scale = frames.scale();
  return frames.frame(phase, short_title);
}

}  // namespace mmv

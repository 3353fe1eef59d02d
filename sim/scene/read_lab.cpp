// The scene's optional `lab:` section (facility/lab.hpp): the room the article hangs
// in, for renders and the envelope check. `lab: {}` is the report's laboratory.
#include "sim/scene/reader_util.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "sim/scene/programs.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::scene_detail {

facility::LabSpec readLab(const YamlReader& r, const YAML::Node& n) {
  struct Key {
    const char* name;
    double facility::LabSpec::*field;
    bool may_be_zero;
  };
  static const Key keys[] = {
      {"floor_length_m", &facility::LabSpec::floor_length, false},
      {"floor_width_m", &facility::LabSpec::floor_width, false},
      {"ceiling_height_m", &facility::LabSpec::ceiling_height, false},
      {"platform_height_m", &facility::LabSpec::platform_height, false},
      {"hole_side_m", &facility::LabSpec::hole_side, false},
      {"platform_length_m", &facility::LabSpec::platform_length, false},
      {"platform_width_m", &facility::LabSpec::platform_width, false},
      {"platform_thickness_m", &facility::LabSpec::platform_thickness, false},
      {"base_below_platform_m", &facility::LabSpec::base_below_platform, true},
  };
  std::vector<std::string> names;
  for (const Key& k : keys) names.push_back(k.name);
  const auto m = r.mapping(n, "lab", names);
  facility::LabSpec lab;
  for (const Key& k : keys) {
    if (!m.count(k.name)) continue;
    const std::string path = std::string("lab.") + k.name;
    lab.*k.field = k.may_be_zero ? r.nonNegative(m.at(k.name), path, " m") : r.positive(m.at(k.name), path, " m");
  }
  // The relations between them, each reported at the key that breaks it (or the section).
  auto at = [&](const char* key) { return m.count(key) ? m.at(key).Mark() : n.Mark(); };
  auto need = [&](bool ok, const char* key, const std::string& what) {
    if (!ok) r.fail(at(key), std::string("lab.") + key + ": " + what);
  };
  need(lab.platform_height + lab.platform_thickness < lab.ceiling_height, "platform_height_m",
       strf("the platform (%g m, %g m thick) must be below the ceiling (%g m)", lab.platform_height,
            lab.platform_thickness, lab.ceiling_height));
  need(lab.platform_thickness < lab.platform_height, "platform_thickness_m",
       strf("the platform's thickness (%g m) must be less than its height (%g m)", lab.platform_thickness,
            lab.platform_height));
  need(lab.hole_side < std::min(lab.platform_length, lab.platform_width), "hole_side_m",
       strf("the hole (%g m) must be smaller than the platform (%g m x %g m)", lab.hole_side, lab.platform_length,
            lab.platform_width));
  need(lab.platform_length <= lab.floor_length, "platform_length_m",
       strf("the platform (%g m) must fit over the floor (%g m)", lab.platform_length, lab.floor_length));
  need(lab.platform_width <= lab.floor_width, "platform_width_m",
       strf("the platform (%g m) must fit over the floor (%g m)", lab.platform_width, lab.floor_width));
  return lab;
}

namespace {

/// `shaker.program`: the force program of time runs, within the shaker's force limit
/// (a random program's RMS times its crest factor), on a station, through an armature
/// with mass, on segment links (the stinger closes the tree: no links in modal
/// coordinates).
void readShakerProgram(const YamlReader& r, const YAML::Node& pn, const ArticleSpec& article, ShakerSceneSpec& s) {
  const TableMotion p = readTableMotion(r, pn, "shaker.program", {}, " N");
  if (s.autoAt())
    r.fail(pn.Mark(), "shaker.program drives the shaker where it is attached: give shaker.at a station and shaker.direction "
                      "its force's direction ('auto' is place-sensors' choice; it prints the station and direction it ranks first)");
  if (!(s.hardware.armature_mass > 0))
    r.fail(pn.Mark(), "shaker.program drives the shaker's armature, which needs its mass: shaker.armature_mass_kg > 0 (got 0; "
                      "the report's shaker is assumed at 0.5 kg)");
  for (const auto& l : article.links)
    if (l.modes > 0)
      r.fail(pn.Mark(), "shaker.program: the stinger holds the armature to the article, which closes the tree, and links in "
                        "modal coordinates need an open tree: remove links." + l.name + ".modes (the run uses its segments)");
  const double limit = s.hardware.force_limit;
  if (p.type == TableMotion::Type::Random) {
    if (p.rms * s.hardware.crest_factor > limit * (1 + 1e-12))
      r.fail(pn.Mark(), strf("shaker.program: an RMS force of %g N at the crest factor %g peaks at %g N, above the shaker's "
                             "force limit of %g N (shaker.force_limit_n): lower rms to %g N or less",
                             p.rms, s.hardware.crest_factor, p.rms * s.hardware.crest_factor, limit, limit / s.hardware.crest_factor));
  } else {
    const double peak = p.type == TableMotion::Type::Profile
                            ? facility::checkProgram(*makeTableProgram(p), facility::TableSpec{INFINITY}).peak_displacement
                            : std::abs(p.amplitude);
    if (peak > limit * (1 + 1e-12))
      r.fail(pn.Mark(), strf("shaker.program: its peak force of %g N is above the shaker's force limit of %g N "
                             "(shaker.force_limit_n): lower it, or set the lab's shaker's limit",
                             peak, limit));
  }
  s.program = p;
}

}  // namespace

ShakerSceneSpec readShaker(const YamlReader& r, const YAML::Node& n, const ArticleSpec& article) {
  const auto m =
      r.mapping(n, "shaker", {"at", "direction", "force_limit_n", "stroke_m", "armature_mass_kg", "crest_factor", "program"});
  ShakerSceneSpec s;
  const YAML::Node& at = r.require(m, n, "shaker", "at");
  s.at = r.text(at, "shaker.at");
  if (!s.autoAt()) {
    std::string error;
    const std::optional<StationSpec> st = parseStation(s.at, article, error);
    if (!st)
      r.fail(at.Mark(), "shaker.at: the shaker must be attached to the article at a station, LINK@DISTm or LINK@FRACTION "
                        "(e.g. link2@1.2m), or 'auto' for the best-ranked one: " + (isStationName(s.at) ? error : "got '" + s.at + "'"));
    if (st->offset != 0 || st->offset_z != 0)
      r.fail(at.Mark(), "shaker.at: the stinger attaches on the link's axis: give the station without an offset (got '" + s.at + "')");
  }
  const YAML::Node& dir = r.require(m, n, "shaker", "direction");
  if (dir.IsScalar() && dir.Scalar() == "auto") {
    s.auto_direction = true;
  } else {
    s.direction = r.vec3(dir, "shaker.direction");
    const Eigen::Vector3d d(s.direction[0], s.direction[1], s.direction[2]);
    if (!(d.norm() > 1e-12)) r.fail(dir.Mark(), "shaker.direction must not be zero: give the force's direction in the world, e.g. [0, 1, 0], or 'auto'");
    if (d[2] != 0 && article.model != ArticleModel::Spatial)
      r.fail(dir.Mark(), "shaker.direction leaves the plane of motion (z = " + dir[2].Scalar() + "): it needs model: spatial");
    const Eigen::Vector3d u = d.normalized();
    s.direction = {u[0], u[1], u[2]};
  }
  if (s.autoAt() != s.auto_direction)
    r.fail(dir.Mark(), "shaker: 'auto' chooses the station and the direction together: give both as 'auto', or neither");
  auto within = [&](const char* key, double lo, double hi, const char* unit, double& field) {
    if (!m.count(key)) return;
    const double v = r.number(m.at(key), std::string("shaker.") + key);
    if (!(v >= lo && v <= hi))
      r.fail(m.at(key).Mark(), strf("shaker.%s must be between %g and %g%s (got %s)", key, lo, hi, unit, m.at(key).Scalar().c_str()));
    field = v;
  };
  within("force_limit_n", 1e-3, 1e6, " N", s.hardware.force_limit);
  within("stroke_m", 1e-6, 10, " m", s.hardware.stroke);
  within("armature_mass_kg", 0, 1000, " kg", s.hardware.armature_mass);
  within("crest_factor", 1, 10, "", s.hardware.crest_factor);
  if (m.count("program")) readShakerProgram(r, m.at("program"), article, s);
  return s;
}

/// views: {NAME: {eye: [x, y, z], target: [x, y, z], up: [x, y, z], fov_deg: F}}.
void readViews(const YamlReader& r, const YAML::Node& n, ArticleScene& scene) {
  auto m = r.mapping(n, "views", namesOf(r, n, "views"));
  for (const auto& [name, node] : m) {
    const std::string path = "views." + name;
    auto v = r.mapping(node, path, {"eye", "target", "up", "fov_deg"});
    CameraView c;
    c.name = name;
    c.eye = r.vec3(r.require(v, node, path, "eye"), path + ".eye");
    c.target = r.vec3(r.require(v, node, path, "target"), path + ".target");
    if (v.count("up")) c.up = r.vec3(v.at("up"), path + ".up");
    if (v.count("fov_deg")) {
      c.fov_deg = r.positive(v.at("fov_deg"), path + ".fov_deg", " deg");
      if (c.fov_deg >= 170) r.fail(v.at("fov_deg").Mark(), path + ".fov_deg must be below 170 deg (got " + v.at("fov_deg").Scalar() + ")");
    }
    const Eigen::Vector3d eye(c.eye[0], c.eye[1], c.eye[2]), target(c.target[0], c.target[1], c.target[2]),
        up(c.up[0], c.up[1], c.up[2]);
    const Eigen::Vector3d look = target - eye;
    if (!(look.norm() > 1e-9)) r.fail(node.Mark(), path + ": eye and target must differ");
    if (!(up.cross(look).norm() > 1e-9 * look.norm() * std::max(up.norm(), 1e-300)))
      r.fail(node.Mark(), path + ".up must not be parallel to the line of sight (or zero)");
    scene.views.push_back(c);
  }
}

}  // namespace mmv::scene_detail

// Scene sections of an article (materials and sections: read_section.cpp): base (table, gimbal), joints,
// links, closures, loads; the tree check.
#include <Eigen/Dense>
#include <algorithm>
#include <optional>
#include <set>

#include "sim/core/integrators.hpp"
#include "sim/scene/programs.hpp"
#include "sim/scene/reader_util.hpp"

namespace mmv::scene_detail {

namespace {

/// {mass, rotary_inertia, offset: [y, z]}; `offset_z` gets the offset's position when its
/// z is not 0 (the spatial model's, checked once the model is known).
LumpedMass readLumpedMass(const YamlReader& r, const YAML::Node& n, const std::string& path,
                          std::optional<Located>& offset_z) {
  auto m = r.mapping(n, path, {"mass", "rotary_inertia", "offset"});
  LumpedMass out;
  out.mass = r.positive(r.require(m, n, path, "mass"), path + ".mass", " kg");
  if (m.count("rotary_inertia"))
    out.rotary_inertia = r.nonNegative(m.at("rotary_inertia"), path + ".rotary_inertia", " kg*m^2");
  if (m.count("offset")) {
    const YAML::Node& o = m.at("offset");
    if (!o.IsSequence() || o.size() != 2)
      r.fail(o.Mark(), path + ".offset must be [y, z] in m, across the link's section (got " + YamlReader::show(o) + ")");
    out.offset = {r.number(o[0], path + ".offset[0]"), r.number(o[1], path + ".offset[1]")};
    if (out.offset[1] != 0 && !offset_z) offset_z = Located{o.Mark(), path + ".offset"};
  }
  return out;
}

class SceneParser {
 public:
  SceneParser(const YamlReader& r) : r_(r) {}

  ArticleScene parse(const YAML::Node& root, const std::string& source) {
    auto top = r_.mapping(root, "", {"name", "gravity", "materials", "sections", "base", "joints",
                                     "links", "closures", "loads", "damping", "simulation", "sensors", "views", "lab",
                                     "shaker", "model", "instruments", "strength"});
    ArticleScene scene;
    scene.source = source;
    scene.name = top.count("name") ? r_.text(top.at("name"), "name") : std::string("unnamed");
    if (top.count("gravity")) {
      scene.gravity = r_.vec3(top.at("gravity"), "gravity");
      if (scene.gravity[2] != 0.0)
        r_.fail(top.at("gravity")[2].Mark(),
                "gravity[2] must be 0 m/s^2: the article moves in the x-y plane (got " +
                    top.at("gravity")[2].Scalar() + ")");
    }
    ArticleSpec& a = scene.article;
    readMaterials(r_.require(top, root, "", "materials"), a);
    readSections(r_.require(top, root, "", "sections"), a);
    if (top.count("strength")) a.strength = readStrengthFactors(r_, top.at("strength"));
    if (top.count("base")) readBase(top.at("base"), a.base);
    readJoints(r_.require(top, root, "", "joints"), a);
    readLinks(r_.require(top, root, "", "links"), a);
    checkTree(a);
    resolveModels(top.count("model") ? &top.at("model") : nullptr, a);  // before the sensors, whose axes depend on it
    if (top.count("closures")) readClosures(top.at("closures"), a);
    if (top.count("loads")) readLoads(top.at("loads"), a);
    if (top.count("damping")) scene.damping = readDamping(r_, top.at("damping"));
    scene.simulation.fidelity = SimulationSpec::Fidelity::Auto;  // a scene file's defaults (sim/time/fidelity.hpp)
    scene.simulation.integrator.clear();
    if (top.count("simulation")) scene.simulation = readSimulation(r_, top.at("simulation"), true);
    scene.instruments = reportInstruments();
    if (top.count("instruments")) readInstruments(r_, top.at("instruments"), scene);
    if (top.count("sensors")) readSensors(r_, top.at("sensors"), scene);
    if (top.count("views")) readViews(r_, top.at("views"), scene);
    if (top.count("lab")) scene.lab = readLab(r_, top.at("lab"));
    if (top.count("shaker")) scene.shaker = readShaker(r_, top.at("shaker"), a);
    if (a.base.motion) checkStroke(*a.base.motion, scene.simulation.duration, motion_mark_, "base.motion");
    if (a.base.motion_z) {
      checkStroke(*a.base.motion_z, scene.simulation.duration, *motion_z_mark_, "base.motion_z");
      if (a.model != ArticleModel::Spatial)
        r_.fail(*motion_z_mark_, "base.motion_z moves the table across the plane of motion: it needs model: spatial");
    }
    if (out_of_plane_mark_ && a.model != ArticleModel::Spatial)
      r_.fail(out_of_plane_mark_->mark, out_of_plane_mark_->path + ": branches out of the plane need model: spatial");
    if (offset_z_mark_ && a.model != ArticleModel::Spatial)
      r_.fail(offset_z_mark_->mark, offset_z_mark_->path + ": a mass offset out of the plane needs model: spatial");
    if (modes_mark_ && (a.model != ArticleModel::Planar || !a.closures.empty()))
      r_.fail(modes_mark_->mark, modes_mark_->path + ": links in modal coordinates need a planar open tree (this article is " +
                                     (a.model != ArticleModel::Planar ? "spatial)" : "closed)"));
    return scene;
  }

 private:
  /// The slew the facility would make from `from` (rad) within +-range: refused here,
  /// at its key, rather than when the model is built.
  void checkSlew(const YAML::Node& n, const std::string& path, const SlewSpec& slew, double from, double range, bool continuous) {
    try {
      // An angle program as written starts at the joint's own angle: said before its range.
      const double start = makeSlew(slew, from, INFINITY, true).writtenStart();
      if (std::abs(start - from) > 1e-9)
        r_.fail(n.Mark(), path + strf(": angle program: it starts at %.6g deg, the joint at %.6g deg (its angle_deg): the first "
                                      "angle must be the joint's", start / kDegToRad, from / kDegToRad));
      (void)makeSlew(slew, from, range, continuous);
    } catch (const std::invalid_argument& e) {
      r_.fail(n.Mark(), path + ": " + e.what());
    }
  }

  /// range_deg: degrees > 0, or `unlimited` (a slip ring: `continuous`, and the range pi,
  /// the travel over which a holding torque is worst).
  void readRange(const YAML::Node& n, const std::string& path, double& range, bool& continuous) {
    if (n.IsScalar() && n.Scalar() == "unlimited") {
      continuous = true;
      range = M_PI;
      return;
    }
    range = r_.positive(n, path, " deg") * kDegToRad;
  }

  /// The table program must stay within the table's stroke over the scene's run.
  void checkStroke(const TableMotion& motion, double duration, const YAML::Mark& mark, const std::string& key) {
    const facility::ProgramCheck check = facility::checkProgram(*makeTableProgram(motion), {}, duration);
    if (!check.within_stroke) r_.fail(mark, key + ": " + check.messages.front());
  }

  void readMaterials(const YAML::Node& n, ArticleSpec& a) {
    auto m = r_.mapping(n, "materials", namesOf(r_, n, "materials"));
    for (const auto& [name, node] : m) {
      const std::string path = "materials." + name;
      a.materials.push_back(readMaterial(r_, name, node, path));
    }
  }

  ArticleModel readModelName(const YAML::Node& n, const std::string& path) {
    const std::string v = r_.text(n, path);
    if (v == "planar") return ArticleModel::Planar;
    if (v != "spatial") r_.fail(n.Mark(), path + ": unknown model '" + v + "' (known: planar, spatial)");
    return ArticleModel::Spatial;
  }

  /// model: planar | spatial, the scene's (`n`, may be null) and each link's own. The
  /// article is spatial when any link is; a link without a model of its own takes the
  /// scene's. A link that bends out of its plane twists, so it needs its material's
  /// shear modulus and, for an explicit section, its out-of-plane moment and torsion
  /// constant (named at the key that asked for it).
  void resolveModels(const YAML::Node* n, ArticleSpec& a) {
    const ArticleModel scene_model = n ? readModelName(*n, "model") : ArticleModel::Planar;
    a.model = scene_model;
    const bool any_spatial = std::any_of(a.links.begin(), a.links.end(),
                                         [](const LinkSpec& l) { return l.model == ArticleModel::Spatial; });
    if (scene_model == ArticleModel::Planar && any_spatial) {  // the article is spatial, the others stay planar
      a.model = ArticleModel::Spatial;
      for (auto& l : a.links)
        if (!l.model) l.model = ArticleModel::Planar;
    }
    for (const auto& l : a.links) {
      if (l.rigid || !a.bendsOutOfPlane(l)) continue;
      const auto own = link_model_marks_.find(l.name);
      const Located at = own != link_model_marks_.end() ? own->second : Located{n->Mark(), "model"};
      const Material& m = *a.findMaterial(l.material);
      if (!(m.shear_modulus > 0))
        r_.fail(at.mark, at.path + ": spatial twists link '" + l.name + "': materials." + m.name +
                             " needs shear_modulus (Pa) or poisson_ratio");
      const Section& s = *a.findSection(l.section);
      if (!(sectionSecondMomentOut(s) > 0) || !(sectionTorsionConstant(s) > 0))
        r_.fail(at.mark, at.path + ": spatial bends link '" + l.name + "' out of its plane: sections." + s.name +
                             " needs second_moment_out and torsion_constant (m^4)");
    }
  }

  void readSections(const YAML::Node& n, ArticleSpec& a) {
    auto m = r_.mapping(n, "sections", namesOf(r_, n, "sections"));
    for (const auto& [name, node] : m) a.sections.push_back(readSection(r_, name, node, "sections." + name));
  }

  /// base.gimbal: {yaw|pitch|roll: {angle_deg, slew, range_deg, torque_capacity}, ring_mass, ring_inertia}.
  /// A commanded angle or a slew's end beyond the axis's range is an error at its line.
  GimbalSpec readGimbal(const YAML::Node& n) {
    auto m = r_.mapping(n, "base.gimbal", {"yaw", "pitch", "roll", "ring_mass", "ring_inertia"});
    GimbalSpec g;
    for (const auto& entry : {std::pair<const char*, GimbalAxisSpec*>{"yaw", &g.yaw}, {"pitch", &g.pitch}, {"roll", &g.roll}}) {
      const char* name = entry.first;  // not a structured binding: clang 14 cannot capture those
      GimbalAxisSpec* axis = entry.second;
      if (!m.count(name)) continue;
      const std::string path = std::string("base.gimbal.") + name;
      const YAML::Node& an = m.at(name);
      auto am = r_.mapping(an, path, {"angle_deg", "slew", "range_deg", "torque_capacity"});
      if (am.count("range_deg")) readRange(am.at("range_deg"), path + ".range_deg", axis->range, axis->continuous);
      if (am.count("torque_capacity"))
        axis->torque_capacity = r_.positive(am.at("torque_capacity"), path + ".torque_capacity", " N*m");
      auto within = [&](const YAML::Node& v, double angle, const std::string& key) {
        if (std::abs(angle) > axis->range + 1e-12)
          r_.fail(v.Mark(), key + ": " + v.Scalar() + " deg is beyond the gimbal's +-" +
                                std::to_string(static_cast<int>(std::lround(axis->range / kDegToRad))) + " deg " + name + " range");
      };
      if (am.count("angle_deg")) {
        axis->angle = r_.number(am.at("angle_deg"), path + ".angle_deg") * kDegToRad;
        within(am.at("angle_deg"), axis->angle, path + ".angle_deg");
      }
      if (am.count("slew")) {
        axis->slew = readSlew(r_, am.at("slew"), path + ".slew");
        if (am.at("slew")["to_deg"]) within(am.at("slew")["to_deg"], axis->slew->to, path + ".slew.to_deg");
        checkSlew(am.at("slew"), path + ".slew", *axis->slew, axis->angle, axis->range, axis->continuous);
      }
    }
    if (m.count("ring_mass")) g.ring_mass = r_.positive(m.at("ring_mass"), "base.gimbal.ring_mass", " kg");
    if (m.count("ring_inertia")) g.ring_inertia = r_.positive(m.at("ring_inertia"), "base.gimbal.ring_inertia", " kg*m^2");
    return g;
  }

  void readBase(const YAML::Node& n, BaseSpec& b) {
    auto m = r_.mapping(n, "base", {"type", "position", "direction_deg", "table_mass", "motion", "motion_z", "gimbal"});
    if (m.count("type")) {
      const std::string t = r_.text(m.at("type"), "base.type");
      if (t == "table") b.type = BaseType::Table;
      else if (t != "fixed") r_.fail(m.at("type").Mark(), "base.type: unknown base type '" + t + "' (known: fixed, table)");
    }
    for (const char* k : {"table_mass", "motion", "motion_z"})
      if (m.count(k) && b.type != BaseType::Table) r_.fail(m.at(k).Mark(), std::string("base.") + k + " applies only with type: table");
    if (m.count("table_mass")) b.table_mass = r_.positive(m.at("table_mass"), "base.table_mass", " kg");
    if (m.count("motion")) {
      b.motion = readTableMotion(r_, m.at("motion"), "base.motion", {});
      motion_mark_ = m.at("motion").Mark();
    }
    if (m.count("motion_z")) {
      b.motion_z = readTableMotion(r_, m.at("motion_z"), "base.motion_z", {});
      motion_z_mark_ = m.at("motion_z").Mark();
    }
    if (m.count("position")) {
      b.position = r_.vec3(m.at("position"), "base.position");
      if (b.position[2] != 0.0)
        r_.fail(m.at("position")[2].Mark(), "base.position[2] must be 0 m: the article moves in the x-y plane (got " +
                                                m.at("position")[2].Scalar() + ")");
    }
    if (m.count("direction_deg")) b.direction = r_.number(m.at("direction_deg"), "base.direction_deg") * kDegToRad;
    if (m.count("gimbal")) b.gimbal = readGimbal(m.at("gimbal"));
  }

  void checkName(const YAML::Node& n, const std::string& path, const std::string& name) {
    if (name == "base") r_.fail(n.Mark(), path + ": the name 'base' is reserved (got base)");
    if (name.find_first_of(". \t/") != std::string::npos)
      r_.fail(n.Mark(), path + " must not contain '.', '/' or spaces (got " + name + ")");
    if (!names_.insert(name).second)
      r_.fail(n.Mark(), path + ": name '" + name + "' is used twice among joints and links");
  }

  /// The joint's range (range_deg; the report's torquers: +-45 deg): a held or servo
  /// angle beyond it is refused at its line, as are a slew's ends (checkSlew); a free
  /// joint's starting angle only within +-180 deg.
  void checkJointRange(const std::map<std::string, YAML::Node>& m, const std::string& path, JointSpec& j) {
    if (m.count("range_deg")) {
      readRange(m.at("range_deg"), path + ".range_deg", j.range, j.continuous);
      if (j.range > M_PI + 1e-12)
        r_.fail(m.at("range_deg").Mark(), path + ".range_deg must be <= 180 deg, or unlimited (got " + m.at("range_deg").Scalar() + ")");
    }
    if (!m.count("angle_deg")) return;
    const double limit = j.hold == JointHold::Free ? M_PI : j.range;
    if (std::abs(j.angle) > limit + 1e-12)
      r_.fail(m.at("angle_deg").Mark(),
              path + ".angle_deg: " + m.at("angle_deg").Scalar() + " deg is beyond the joint's +-" +
                  strf("%g", limit / kDegToRad) +
                  (j.hold == JointHold::Free ? " deg" : " deg range (its torquer's; range_deg sets another)"));
  }

  void readJoints(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "joints");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& jn = n[i];
      const std::string path = "joints[" + std::to_string(i) + "]";
      auto m = r_.mapping(jn, path, {"name", "parent", "angle_deg", "hold", "servo_stiffness", "torquer", "slew",
                                     "torque_capacity", "torque", "range_deg"});
      JointSpec j;
      const YAML::Node& name = r_.require(m, jn, path, "name");
      j.name = r_.text(name, path + ".name");
      checkName(name, path + ".name", j.name);
      j.parent = r_.text(r_.require(m, jn, path, "parent"), path + ".parent");
      joint_parent_marks_[j.name] = {m.at("parent").Mark(), path + ".parent"};
      if (m.count("angle_deg")) j.angle = r_.number(m.at("angle_deg"), path + ".angle_deg") * kDegToRad;
      if (m.count("hold")) {
        const std::string h = r_.text(m.at("hold"), path + ".hold");
        if (h == "locked") j.hold = JointHold::Locked;
        else if (h == "free") j.hold = JointHold::Free;
        else if (h == "servo") j.hold = JointHold::Servo;
        else r_.fail(m.at("hold").Mark(), path + ".hold: unknown hold '" + h + "' (known: locked, free, servo)");
      }
      if (j.hold == JointHold::Servo) {
        j.servo_stiffness = r_.positive(r_.require(m, jn, path, "servo_stiffness"),
                                        path + ".servo_stiffness", " N*m/rad");
      } else if (m.count("servo_stiffness")) {
        r_.fail(m.at("servo_stiffness").Mark(), path + ".servo_stiffness applies only with hold: servo");
      }
      checkJointRange(m, path, j);
      if (m.count("torquer")) j.torquer = readLumpedMass(r_, m.at("torquer"), path + ".torquer", offset_z_mark_);
      if (m.count("torque_capacity"))
        j.torque_capacity = r_.positive(m.at("torque_capacity"), path + ".torque_capacity", " N*m");
      if (m.count("slew")) {
        const YAML::Node& sn = m.at("slew");
        if (j.hold != JointHold::Locked)
          r_.fail(sn.Mark(), path + ".slew: only a locked joint (its torquer holding the angle) follows a slew");
        j.slew = readSlew(r_, sn, path + ".slew");
        checkSlew(sn, path + ".slew", *j.slew, j.angle, j.range, j.continuous);
      }
      if (m.count("torque")) {
        const YAML::Node& tn = m.at("torque");
        if (j.hold == JointHold::Locked)
          r_.fail(tn.Mark(), path + ".torque: a commanded torque needs a joint that moves (hold: free or servo)");
        j.torque_input = readTableMotion(r_, tn, path + ".torque", {}, " N*m");
      }
      joint_marks_[j.name] = {jn.Mark(), path};
      a.joints.push_back(j);
    }
  }

  void readLinks(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "links");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& ln = n[i];
      const std::string path = "links[" + std::to_string(i) + "]";
      auto m = r_.mapping(ln, path, {"name", "joint", "material", "section", "length", "segments",
                                     "mount_angle_deg", "tip_mass", "branches", "model", "modes"});
      LinkSpec l;
      const YAML::Node& name = r_.require(m, ln, path, "name");
      l.name = r_.text(name, path + ".name");
      const YAML::Node& joint = r_.require(m, ln, path, "joint");
      l.joint = r_.text(joint, path + ".joint");
      r_.known(joint, path + ".joint", "joint", l.joint, a.joints);
      const YAML::Node& mat = r_.require(m, ln, path, "material");
      l.material = r_.text(mat, path + ".material");
      r_.known(mat, path + ".material", "material", l.material, a.materials);
      const YAML::Node& sec = r_.require(m, ln, path, "section");
      l.section = r_.text(sec, path + ".section");
      r_.known(sec, path + ".section", "section", l.section, a.sections);
      l.length = r_.positive(r_.require(m, ln, path, "length"), path + ".length", " m");
      const YAML::Node& seg = r_.require(m, ln, path, "segments");
      if (seg.IsScalar() && seg.Scalar() == "rigid") {
        l.rigid = true;
      } else {
        if (!seg.IsScalar()) r_.fail(seg.Mark(), path + ".segments must be an integer >= 1 or 'rigid' (got " + YamlReader::show(seg) + ")");
        char* end = nullptr;
        const long v = std::strtol(seg.Scalar().c_str(), &end, 10);
        if (*end != '\0' || end == seg.Scalar().c_str() || v < 1 || v > limits::kMaxSegments)
          r_.fail(seg.Mark(), path + ".segments must be an integer from 1 to " + std::to_string(limits::kMaxSegments) +
                                  " or 'rigid' (got " + seg.Scalar() + ")");
        l.segments = static_cast<int>(v);
      }
      if (m.count("mount_angle_deg")) l.mount_angle = r_.number(m.at("mount_angle_deg"), path + ".mount_angle_deg") * kDegToRad;
      if (m.count("tip_mass")) l.tip_mass = readLumpedMass(r_, m.at("tip_mass"), path + ".tip_mass", offset_z_mark_);
      if (m.count("model")) l.model = readModelName(m.at("model"), path + ".model");
      if (m.count("modes")) {
        const YAML::Node& k = m.at("modes");
        l.modes = r_.integer(k, path + ".modes");
        if (l.rigid || l.modes < 1 || l.modes > l.segments)
          r_.fail(k.Mark(), path + ".modes must be 1 to the link's " + (l.rigid ? "hinges (a rigid link has none)" : std::to_string(l.segments) + " hinges (one per segment)") + " (got " + k.Scalar() + ")");
        modes_mark_ = Located{k.Mark(), path + ".modes"};
      }

      int count = 1;
      double spread = 0;
      out_of_plane_ = false;
      if (m.count("branches")) {
        const YAML::Node& bn = m.at("branches");
        auto bm = r_.mapping(bn, path + ".branches", {"count", "angle_deg", "plane"});
        const YAML::Node& c = r_.require(bm, bn, path + ".branches", "count");
        count = r_.integer(c, path + ".branches.count");
        if (count < 1 || count > 26) r_.fail(c.Mark(), path + ".branches.count must be 1 to 26 (got " + c.Scalar() + ")");
        if (count > 1) spread = r_.number(r_.require(bm, bn, path + ".branches", "angle_deg"), path + ".branches.angle_deg") * kDegToRad;
        if (bm.count("plane")) {
          const std::string plane = r_.text(bm.at("plane"), path + ".branches.plane");
          if (plane != "in" && plane != "out")
            r_.fail(bm.at("plane").Mark(), path + ".branches.plane: unknown plane '" + plane + "' (known: in, out)");
          if (plane == "out") {
            out_of_plane_ = true;
            if (!out_of_plane_mark_) out_of_plane_mark_ = Located{bm.at("plane").Mark(), path + ".branches.plane"};
          }
        }
      }
      for (int k = 0; k < count; ++k) {
        LinkSpec b = l;
        if (count > 1) {
          b.name = l.name + static_cast<char>('a' + k);
          (out_of_plane_ ? b.tilt : b.mount_angle) += -0.5 * spread + spread * k / (count - 1);
        }
        checkName(name, path + ".name", b.name);
        b.key = path;
        link_marks_[b.name] = {ln.Mark(), path};
        if (m.count("model")) link_model_marks_[b.name] = {m.at("model").Mark(), path + ".model"};
        a.links.push_back(b);
      }
    }
  }

  void readClosures(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "closures");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& cn = n[i];
      const std::string path = "closures[" + std::to_string(i) + "]";
      auto m = r_.mapping(cn, path, {"name", "point", "to", "type", "at", "direction_deg"});
      ClosureSpec c;
      c.name = m.count("name") ? r_.text(m.at("name"), path + ".name") : "closure" + std::to_string(i + 1);
      c.point = readPoint(r_, r_.require(m, cn, path, "point"), path + ".point", a);
      if (m.count("to") && r_.text(m.at("to"), path + ".to") != "ground") {
        c.to = readPoint(r_, m.at("to"), path + ".to", a);
        if (c.to == c.point) r_.fail(m.at("to").Mark(), path + ".to must differ from its point (got " + c.to + ")");
        if (m.count("at")) r_.fail(m.at("at").Mark(), path + ".at applies only to closures to the ground");
      }
      if (m.count("type")) {
        const std::string t = r_.text(m.at("type"), path + ".type");
        if (t == "pin" || t == "ball") c.type = ClosureType::Pin;
        else if (t == "slider") c.type = ClosureType::Slider;
        else r_.fail(m.at("type").Mark(), path + ".type: unknown closure type '" + t + "' (known: pin, ball, slider)");
      }
      if (m.count("direction_deg")) {
        if (c.type != ClosureType::Slider)
          r_.fail(m.at("direction_deg").Mark(), path + ".direction_deg applies only with type: slider");
        c.direction = r_.number(m.at("direction_deg"), path + ".direction_deg") * kDegToRad;
      }
      if (m.count("at") && c.to == "ground") {
        c.at = r_.vec3(m.at("at"), path + ".at");
        if ((*c.at)[2] != 0.0)
          r_.fail(m.at("at")[2].Mark(), path + ".at[2] must be 0 m: the article moves in the x-y plane (got " +
                                            m.at("at")[2].Scalar() + ")");
      }
      c.where = r_.position(cn.Mark());
      a.closures.push_back(c);
    }
  }

  void readLoads(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "loads");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& ln = n[i];
      const std::string path = "loads[" + std::to_string(i) + "]";
      auto m = r_.mapping(ln, path, {"point", "force"});
      LoadSpec l;
      l.point = readPoint(r_, r_.require(m, ln, path, "point"), path + ".point", a);
      const YAML::Node& f = r_.require(m, ln, path, "force");
      l.force = r_.vec3(f, path + ".force");
      if (l.force[2] != 0.0 && a.model != ArticleModel::Spatial)
        r_.fail(f[2].Mark(), path + ".force[2] must be 0 N: the planar article moves in the x-y plane (got " + f[2].Scalar() +
                                 "; a load out of the plane needs model: spatial)");
      l.where = r_.position(ln.Mark());
      a.loads.push_back(l);
    }
  }

  /// Every joint hangs from the base or an existing link, carries a link, and the
  /// links form a tree rooted at the base.
  void checkTree(const ArticleSpec& a) {
    for (const auto& j : a.joints) {
      if (j.parent != "base" && !a.findLink(j.parent)) {
        std::vector<std::string> known{"base"};
        for (const auto& l : a.links) known.push_back(l.name);
        const auto& loc = joint_parent_marks_.at(j.name);
        r_.fail(loc.mark, loc.path + ": unknown parent '" + j.parent + "' (known: " + joinNames(known) + ")");
      }
      bool carries = false;
      for (const auto& l : a.links) carries = carries || l.joint == j.name;
      if (!carries) {
        const auto& loc = joint_marks_.at(j.name);
        r_.fail(loc.mark, loc.path + ": joint '" + j.name + "' carries no link");
      }
    }
    for (const auto& l : a.links) {
      // Walk towards the base; a walk longer than the number of links is a cycle.
      std::string at = l.name;
      for (std::size_t steps = 0;; ++steps) {
        const LinkSpec* cur = a.findLink(at);
        const std::string parent = a.findJoint(cur->joint)->parent;
        if (parent == "base") break;
        if (steps > a.links.size()) {
          const auto& loc = link_marks_.at(l.name);
          r_.fail(loc.mark, loc.path + ": link '" + l.name + "' is not connected to the base (its joints form a loop)");
        }
        at = parent;
      }
    }
  }

  const YamlReader& r_;
  std::set<std::string> names_;
  std::map<std::string, Located> joint_marks_, joint_parent_marks_, link_marks_;
  std::map<std::string, Located> link_model_marks_;  ///< links with a model of their own.
  YAML::Mark motion_mark_;
  std::optional<YAML::Mark> motion_z_mark_;
  bool out_of_plane_ = false;                  ///< the link being read spreads its branches out of the plane.
  std::optional<Located> out_of_plane_mark_;   ///< the first such `branches.plane: out`.
  std::optional<Located> offset_z_mark_;       ///< the first lumped mass offset out of the plane.
  std::optional<Located> modes_mark_;          ///< the last link in modal coordinates.
};

}  // namespace

ArticleScene readArticleScene(const YamlReader& r, const YAML::Node& root, const std::string& source) {
  return SceneParser(r).parse(root, source);
}

}  // namespace mmv::scene_detail

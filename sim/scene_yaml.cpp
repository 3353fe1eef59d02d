// Scene reader: YAML text -> Scene, with every problem reported as
// "file:line:col: what is wrong (got X)". yaml-cpp accepts duplicate keys silently
// and reports missing keys without a position, so keys are checked here against the
// nodes' marks (see ../shared/DESIGN.md, platform pitfalls).

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "sim/run_integrator.hpp"
#include "sim/scene.hpp"

namespace mmv {
namespace {

constexpr double kDegToRad = M_PI / 180.0;

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

/// Reads one document; knows the file name for messages.
class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  /// "file:line:col"; an empty document has a null mark (-1): the start of the file.
  std::string position(const YAML::Mark& mark) const {
    std::ostringstream os;
    os << file_ << ':' << std::max(mark.line, 0) + 1 << ':' << std::max(mark.column, 0) + 1;
    return os.str();
  }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const {
    throw SceneError(position(mark) + ": " + what);
  }

  static std::string show(const YAML::Node& n) {
    if (n.IsScalar()) return n.Scalar();
    if (n.IsSequence()) return "a list";
    if (n.IsMap()) return "a mapping";
    return "nothing";
  }

  double number(const YAML::Node& n, const std::string& path) const {
    if (!n.IsScalar()) fail(n.Mark(), path + " must be a number (got " + show(n) + ")");
    const std::string& s = n.Scalar();
    std::string lower;
    for (char ch : s) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (lower.find("nan") != std::string::npos || lower.find("inf") != std::string::npos)
      fail(n.Mark(), path + " must be a finite number (got " + s + ")");
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end == s.c_str() || *end != '\0')
      fail(n.Mark(), path + " must be a number (got " + s + ")");
    if (!std::isfinite(v)) fail(n.Mark(), path + " must be a finite number (got " + s + ")");
    return v;
  }

  double positive(const YAML::Node& n, const std::string& path, const std::string& unit) const {
    const double v = number(n, path);
    if (!(v > 0)) fail(n.Mark(), path + " must be > 0" + unit + " (got " + n.Scalar() + ")");
    return v;
  }

  double nonNegative(const YAML::Node& n, const std::string& path, const std::string& unit) const {
    const double v = number(n, path);
    if (v < 0) fail(n.Mark(), path + " must be >= 0" + unit + " (got " + n.Scalar() + ")");
    return v;
  }

  int integer(const YAML::Node& n, const std::string& path) const {
    const double v = number(n, path);
    if (v != std::floor(v) || std::abs(v) > 1e6)
      fail(n.Mark(), path + " must be an integer (got " + n.Scalar() + ")");
    return static_cast<int>(v);
  }

  std::string text(const YAML::Node& n, const std::string& path) const {
    if (!n.IsScalar() || n.Scalar().empty())
      fail(n.Mark(), path + " must be a text value (got " + show(n) + ")");
    return n.Scalar();
  }

  std::array<double, 3> vec3(const YAML::Node& n, const std::string& path) const {
    if (!n.IsSequence() || n.size() != 3)
      fail(n.Mark(), path + " must be a list of 3 numbers (got " + show(n) + ")");
    return {number(n[0], path + "[0]"), number(n[1], path + "[1]"), number(n[2], path + "[2]")};
  }

  /// Checks a mapping: no duplicate keys, only `allowed` keys. Returns key -> node.
  std::map<std::string, YAML::Node> mapping(const YAML::Node& n, const std::string& path,
                                            const std::vector<std::string>& allowed) const {
    if (!n.IsMap()) fail(n.Mark(), path + " must be a mapping of keys (got " + show(n) + ")");
    std::map<std::string, YAML::Node> out;
    for (auto it = n.begin(); it != n.end(); ++it) {
      const YAML::Node& key = it->first;
      if (!key.IsScalar()) fail(key.Mark(), path + ": keys must be text");
      const std::string k = key.Scalar();
      const std::string where = path.empty() ? k : path + "." + k;
      if (out.count(k)) fail(key.Mark(), "duplicate key '" + where + "'");
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == k;
      if (!ok)
        fail(key.Mark(), "unknown key '" + where + "' (allowed: " + joinNames(allowed) + ")");
      out.emplace(k, it->second);
    }
    return out;
  }

  /// A non-empty list; returns its size.
  std::size_t sequence(const YAML::Node& n, const std::string& path) const {
    if (!n.IsSequence() || n.size() == 0) fail(n.Mark(), path + " must be a non-empty list (got " + show(n) + ")");
    return n.size();
  }

  /// Checks that `value` names one of `items` (anything with a .name).
  template <class T>
  void known(const YAML::Node& value, const std::string& path, const std::string& what, const std::string& name,
             const std::vector<T>& items) const {
    std::vector<std::string> names;
    for (const auto& x : items) {
      if (x.name == name) return;
      names.push_back(x.name);
    }
    fail(value.Mark(), path + ": unknown " + what + " '" + name + "' (known: " + joinNames(names) + ")");
  }

  const YAML::Node& require(const std::map<std::string, YAML::Node>& m, const YAML::Node& parent,
                            const std::string& path, const std::string& key) const {
    auto it = m.find(key);
    if (it == m.end())
      fail(parent.Mark(), (path.empty() ? std::string("scene") : path) +
                              " is missing required key '" + key + "'");
    if (it->second.IsNull())
      fail(it->second.Mark(), (path.empty() ? key : path + "." + key) + " has no value");
    return it->second;
  }

 private:
  std::string file_;
};

struct Located {
  YAML::Mark mark;
  std::string path;
};

LumpedMass readLumpedMass(const Reader& r, const YAML::Node& n, const std::string& path) {
  auto m = r.mapping(n, path, {"mass", "rotary_inertia"});
  LumpedMass out;
  out.mass = r.positive(r.require(m, n, path, "mass"), path + ".mass", " kg");
  if (m.count("rotary_inertia"))
    out.rotary_inertia = r.nonNegative(m.at("rotary_inertia"), path + ".rotary_inertia", " kg*m^2");
  return out;
}

Section readSection(const Reader& r, const std::string& name, const YAML::Node& n,
                    const std::string& path) {
  auto m = r.mapping(n, path, {"shape", "b", "h", "t", "radius", "area", "second_moment"});
  Section s;
  s.name = name;
  const YAML::Node& shape = r.require(m, n, path, "shape");
  const std::string kind = r.text(shape, path + ".shape");
  auto need = [&](const char* key) -> const YAML::Node& { return r.require(m, n, path, key); };
  auto forbid = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (m.count(k))
        r.fail(m.at(k).Mark(), path + "." + k + " does not apply to shape '" + kind + "'");
  };
  if (kind == "rectangle") {
    s.shape = SectionShape::Rectangle;
    forbid({"t", "radius", "area", "second_moment"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
  } else if (kind == "rectangular_tube") {
    s.shape = SectionShape::RectangularTube;
    forbid({"radius", "area", "second_moment"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
    s.t = r.positive(need("t"), path + ".t", " m");
    if (2 * s.t >= std::min(s.b, s.h))
      r.fail(need("t").Mark(), path + ".t must be < min(b, h)/2 m so the tube has a hole (got " +
                                   need("t").Scalar() + ")");
  } else if (kind == "round_rod") {
    s.shape = SectionShape::RoundRod;
    forbid({"b", "h", "t", "area", "second_moment"});
    s.radius = r.positive(need("radius"), path + ".radius", " m");
  } else if (kind == "explicit") {
    s.shape = SectionShape::Explicit;
    forbid({"b", "h", "t", "radius"});
    s.explicit_area = r.positive(need("area"), path + ".area", " m^2");
    s.explicit_second_moment = r.positive(need("second_moment"), path + ".second_moment", " m^4");
  } else {
    r.fail(shape.Mark(), path + ".shape: unknown shape '" + kind +
                             "' (known: rectangle, rectangular_tube, round_rod, explicit)");
  }
  return s;
}

class SceneParser {
 public:
  SceneParser(const Reader& r) : r_(r) {}

  Scene parse(const YAML::Node& root, const std::string& source) {
    if (!root.IsDefined() || root.IsNull())
      r_.fail(root.Mark(), "the scene is empty (expected a mapping with 'links' and 'joints')");
    if (root.IsMap() && root["hamsas"]) return parseHamsas(root, source);
    auto top = r_.mapping(root, "", {"name", "gravity", "materials", "sections", "base", "joints",
                                     "links", "closures", "loads", "damping", "simulation", "sensors"});
    Scene scene;
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
    if (top.count("base")) readBase(top.at("base"), a.base);
    readJoints(r_.require(top, root, "", "joints"), a);
    readLinks(r_.require(top, root, "", "links"), a);
    checkTree(a);
    if (top.count("closures")) readClosures(top.at("closures"), a);
    if (top.count("loads")) readLoads(top.at("loads"), a);
    if (top.count("damping")) scene.damping = readDamping(top.at("damping"));
    if (top.count("simulation")) scene.simulation = readSimulation(top.at("simulation"));
    if (top.count("sensors")) readSensors(top.at("sensors"), scene);
    return scene;
  }

 private:
  void readMaterials(const YAML::Node& n, ArticleSpec& a) {
    auto m = r_.mapping(n, "materials", namesOf(n, "materials"));
    for (const auto& [name, node] : m) {
      const std::string path = "materials." + name;
      auto mm = r_.mapping(node, path, {"density", "youngs_modulus"});
      Material mat;
      mat.name = name;
      mat.density = r_.positive(r_.require(mm, node, path, "density"), path + ".density", " kg/m^3");
      mat.youngs_modulus =
          r_.positive(r_.require(mm, node, path, "youngs_modulus"), path + ".youngs_modulus", " Pa");
      a.materials.push_back(mat);
    }
  }

  void readSections(const YAML::Node& n, ArticleSpec& a) {
    auto m = r_.mapping(n, "sections", namesOf(n, "sections"));
    for (const auto& [name, node] : m) a.sections.push_back(readSection(r_, name, node, "sections." + name));
  }

  /// Every key of a name->item mapping is allowed; duplicates are still caught.
  std::vector<std::string> namesOf(const YAML::Node& n, const std::string& path) {
    if (!n.IsMap()) r_.fail(n.Mark(), path + " must be a mapping of names (got " + Reader::show(n) + ")");
    std::vector<std::string> keys;
    for (auto it = n.begin(); it != n.end(); ++it)
      if (it->first.IsScalar()) keys.push_back(it->first.Scalar());
    if (keys.empty()) r_.fail(n.Mark(), path + " must name at least one entry");
    return keys;
  }

  void readSensors(const YAML::Node& n, Scene& scene) {
    const std::size_t count = r_.sequence(n, "sensors");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& sn = n[i];
      const std::string path = "sensors[" + std::to_string(i) + "]";
      auto m = r_.mapping(sn, path, {"name", "type", "joint", "point", "axis", "noise_sigma", "seed"});
      SensorSceneSpec s;
      s.name = r_.text(r_.require(m, sn, path, "name"), path + ".name");
      const YAML::Node& tn = r_.require(m, sn, path, "type");
      s.type = r_.text(tn, path + ".type");
      if (s.type == "encoder") {
        const YAML::Node& jn = r_.require(m, sn, path, "joint");
        s.target = r_.text(jn, path + ".joint");
        r_.known(jn, path + ".joint", "joint", s.target, scene.article.joints);
        if (m.count("point") || m.count("axis")) r_.fail(sn.Mark(), path + ": an encoder reads a joint, not a point or axis");
      } else if (s.type == "rate_gyro" || s.type == "accelerometer") {
        s.target = point(r_.require(m, sn, path, "point"), path + ".point", scene.article);
        if (m.count("joint")) r_.fail(m.at("joint").Mark(), path + ".joint applies only to encoders");
        if (m.count("axis")) {
          if (s.type != "accelerometer") r_.fail(m.at("axis").Mark(), path + ".axis applies only to accelerometers");
          const std::string a = r_.text(m.at("axis"), path + ".axis");
          if (a != "axial" && a != "transverse")
            r_.fail(m.at("axis").Mark(), path + ".axis: unknown axis '" + a + "' (known: axial, transverse)");
          s.axis = a == "transverse";
        }
      } else {
        r_.fail(tn.Mark(), path + ".type: unknown sensor '" + s.type + "' (known: encoder, rate_gyro, accelerometer)");
      }
      if (m.count("noise_sigma")) s.noise_sigma = r_.nonNegative(m.at("noise_sigma"), path + ".noise_sigma", "");
      if (m.count("seed")) s.seed = static_cast<std::uint64_t>(r_.integer(m.at("seed"), path + ".seed"));
      s.where = where(sn);
      scene.sensors.push_back(s);
    }
  }

  SimulationSpec readSimulation(const YAML::Node& n) {
    auto m = r_.mapping(n, "simulation", {"duration", "integrator", "accuracy", "absolute_tolerance", "sample_rate_hz", "start",
                                          "score_points"});
    SimulationSpec s;
    if (m.count("duration")) s.duration = r_.positive(m.at("duration"), "simulation.duration", " s");
    if (m.count("integrator")) s.integrator = r_.text(m.at("integrator"), "simulation.integrator");
    if (m.count("accuracy")) {
      s.accuracy = r_.positive(m.at("accuracy"), "simulation.accuracy", "");
      if (s.accuracy >= 1)
        r_.fail(m.at("accuracy").Mark(), "simulation.accuracy must be below 1 (a relative accuracy; got " + m.at("accuracy").Scalar() + ")");
    }
    if (m.count("absolute_tolerance")) {
      s.absolute_tolerance = r_.positive(m.at("absolute_tolerance"), "simulation.absolute_tolerance", "");
      if (s.absolute_tolerance >= 1)
        r_.fail(m.at("absolute_tolerance").Mark(), "simulation.absolute_tolerance must be below 1 (got " + m.at("absolute_tolerance").Scalar() + ")");
      if (!isSundialsIntegrator(s.integrator))
        r_.fail(m.at("absolute_tolerance").Mark(), "simulation.absolute_tolerance applies to the SUNDIALS integrators "
                                                   "(cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, ida; got integrator " + s.integrator + ")");
    }
    if (m.count("sample_rate_hz")) s.sample_rate_hz = r_.positive(m.at("sample_rate_hz"), "simulation.sample_rate_hz", " Hz");
    if (m.count("start")) {
      const std::string st = r_.text(m.at("start"), "simulation.start");
      if (st != "equilibrium" && st != "rest") r_.fail(m.at("start").Mark(), "simulation.start: unknown start '" + st + "' (known: equilibrium, rest)");
      s.from_equilibrium = st == "equilibrium";
    }
    if (m.count("score_points")) {
      const YAML::Node& sp = m.at("score_points");
      const std::size_t count = r_.sequence(sp, "simulation.score_points");
      for (std::size_t i = 0; i < count; ++i)
        s.score_points.push_back(r_.text(sp[i], "simulation.score_points[" + std::to_string(i) + "]"));
      s.score_where = r_.file() + ":" + std::to_string(sp.Mark().line + 1) + ":" + std::to_string(sp.Mark().column + 1);
    }
    return s;
  }

  /// A table (or ground) motion program; `extra` keys are allowed and left to the caller.
  TableMotion readTableMotion(const YAML::Node& mn, const std::string& path, const std::vector<std::string>& extra,
                              const std::string& unit = " m") {
    std::vector<std::string> keys{"type", "amplitude", "frequency_hz", "ramp_s", "from_hz", "to_hz", "duration", "log", "rms", "seed", "file"};
    keys.insert(keys.end(), extra.begin(), extra.end());
    auto mm = r_.mapping(mn, path, keys);
    const YAML::Node& tn = r_.require(mm, mn, path, "type");
    const std::string t = r_.text(tn, path + ".type");
    auto need = [&](const char* k) -> const YAML::Node& { return r_.require(mm, mn, path, k); };
    auto only = [&](std::initializer_list<const char*> allowed) {
      for (const auto& [k, v] : mm) {
        bool ok = k == "type" || std::find(extra.begin(), extra.end(), k) != extra.end();
        for (const char* a : allowed) ok = ok || k == a;
        if (!ok) r_.fail(v.Mark(), path + "." + k + " does not apply to a " + t + " program");
      }
    };
    TableMotion tm;
    if (t == "sine") {
      only({"amplitude", "frequency_hz", "ramp_s"});
      tm.type = TableMotion::Type::Sine;
      if (mm.count("ramp_s")) tm.ramp = r_.nonNegative(mm.at("ramp_s"), path + ".ramp_s", " s");
      tm.amplitude = r_.number(need("amplitude"), path + ".amplitude");
      tm.frequency_hz = r_.positive(need("frequency_hz"), path + ".frequency_hz", " Hz");
    } else if (t == "sweep") {
      only({"amplitude", "from_hz", "to_hz", "duration", "log"});
      tm.type = TableMotion::Type::Sweep;
      tm.amplitude = r_.number(need("amplitude"), path + ".amplitude");
      tm.from_hz = r_.positive(need("from_hz"), path + ".from_hz", " Hz");
      tm.to_hz = r_.positive(need("to_hz"), path + ".to_hz", " Hz");
      tm.duration = r_.positive(need("duration"), path + ".duration", " s");
      if (mm.count("log")) {
        const std::string l = r_.text(mm.at("log"), path + ".log");
        if (l != "true" && l != "false") r_.fail(mm.at("log").Mark(), path + ".log must be true or false (got " + l + ")");
        tm.logarithmic = l == "true";
      }
    } else if (t == "random") {
      only({"rms", "from_hz", "to_hz", "duration", "seed"});
      tm.type = TableMotion::Type::Random;
      tm.rms = r_.nonNegative(need("rms"), path + ".rms", unit);
      tm.from_hz = r_.positive(need("from_hz"), path + ".from_hz", " Hz");
      tm.to_hz = r_.positive(need("to_hz"), path + ".to_hz", " Hz");
      if (tm.to_hz <= tm.from_hz) r_.fail(mm.at("to_hz").Mark(), path + ".to_hz must be > from_hz (got " + mm.at("to_hz").Scalar() + ")");
      tm.duration = r_.positive(need("duration"), path + ".duration", " s");
      if (mm.count("seed")) tm.seed = static_cast<std::uint64_t>(r_.integer(mm.at("seed"), path + ".seed"));
    } else if (t == "csv") {
      only({"file"});
      tm.type = TableMotion::Type::Profile;
      const YAML::Node& fn = need("file");
      std::filesystem::path file = r_.text(fn, path + ".file");
      if (file.is_relative()) file = std::filesystem::path(r_.file()).parent_path() / file;
      std::ifstream in(file);
      if (!in) r_.fail(fn.Mark(), path + ".file: cannot read profile '" + file.string() + "'");
      std::ostringstream os;
      os << in.rdbuf();
      tm.profile_csv = os.str();
      tm.profile_source = file.string();
    } else {
      r_.fail(tn.Mark(), path + ".type: unknown program '" + t + "' (known: sine, sweep, random, csv)");
    }
    return tm;
  }

  /// A HAM-SAS isolator scene: `name` and `hamsas:` (docs/scene-format.md, docs/hamsas.md).
  Scene parseHamsas(const YAML::Node& root, const std::string& source) {
    auto top = r_.mapping(root, "", {"name", "hamsas", "ground_motion", "simulation"});
    Scene scene;
    scene.source = source;
    scene.name = top.count("name") ? r_.text(top.at("name"), "name") : std::string("unnamed");
    scene.gravity = {0, 0, -9.80665};
    HamsasSpec h;
    std::vector<std::string> allowed{"spherical_joints"};
    for (const HamsasParameter& p : hamsasParameters()) allowed.push_back(p.key);
    const YAML::Node& node = top.at("hamsas");
    auto m = r_.mapping(node, "hamsas", allowed);
    for (const HamsasParameter& p : hamsasParameters()) {
      auto it = m.find(p.key);
      if (it == m.end()) continue;
      const std::string path = std::string("hamsas.") + p.key;
      h.*p.field = p.sign == HamsasParameter::Positive      ? r_.positive(it->second, path, p.unit)
                   : p.sign == HamsasParameter::NonNegative ? r_.nonNegative(it->second, path, p.unit)
                                                            : r_.number(it->second, path);
    }
    if (m.count("spherical_joints")) {
      const std::string j = r_.text(m.at("spherical_joints"), "hamsas.spherical_joints");
      if (j != "stiff" && j != "ideal")
        r_.fail(m.at("spherical_joints").Mark(), "hamsas.spherical_joints must be stiff or ideal (got " + j + ")");
      h.ideal_joints = j == "ideal";
    }
    if (h.lp_length >= h.ip_length) {
      std::ostringstream os;
      os << "hamsas.lp_length must be shorter than hamsas.ip_length = " << h.ip_length << " m (got " << h.lp_length << ")";
      r_.fail((m.count("lp_length") ? m.at("lp_length") : node).Mark(), os.str());
    }
    scene.hamsas = h;
    if (top.count("ground_motion")) {
      const YAML::Node& g = top.at("ground_motion");
      scene.ground_motion = readTableMotion(g, "ground_motion", {"axis"});
      if (g["axis"]) {
        const std::string a = r_.text(g["axis"], "ground_motion.axis");
        if (a != "x" && a != "y" && a != "z") r_.fail(g["axis"].Mark(), "ground_motion.axis must be x, y or z (got " + a + ")");
        scene.ground_axis = a == "x" ? 0 : a == "y" ? 1 : 2;
      }
    }
    if (top.count("simulation")) scene.simulation = readSimulation(top.at("simulation"));
    return scene;
  }

  DampingSpec readDamping(const YAML::Node& n) {
    auto m = r_.mapping(n, "damping", {"modal_ratio", "rayleigh", "hinge_beta"});
    if (m.size() != 1) r_.fail(n.Mark(), "damping must give exactly one of modal_ratio, rayleigh, hinge_beta");
    DampingSpec d;
    if (m.count("modal_ratio")) {
      d.kind = DampingSpec::Kind::Modal;
      d.modal_ratio = r_.nonNegative(m.at("modal_ratio"), "damping.modal_ratio", "");
      if (d.modal_ratio >= 1) r_.fail(m.at("modal_ratio").Mark(), "damping.modal_ratio must be < 1 (got " + m.at("modal_ratio").Scalar() + ")");
    } else if (m.count("rayleigh")) {
      const YAML::Node& rn = m.at("rayleigh");
      auto rm = r_.mapping(rn, "damping.rayleigh", {"alpha", "beta"});
      d.kind = DampingSpec::Kind::Rayleigh;
      if (rm.count("alpha")) d.alpha = r_.nonNegative(rm.at("alpha"), "damping.rayleigh.alpha", " 1/s");
      if (rm.count("beta")) d.beta = r_.nonNegative(rm.at("beta"), "damping.rayleigh.beta", " s");
    } else {
      d.kind = DampingSpec::Kind::HingeViscous;
      d.hinge_beta = r_.positive(m.at("hinge_beta"), "damping.hinge_beta", " s");
    }
    return d;
  }

  SlewSpec readSlew(const YAML::Node& sn, const std::string& path) {
    auto sm = r_.mapping(sn, path, {"to_deg", "start_s", "shape", "max_rate_deg_s", "max_acceleration_deg_s2"});
    SlewSpec sl;
    sl.to = r_.number(r_.require(sm, sn, path, "to_deg"), path + ".to_deg") * kDegToRad;
    if (sm.count("start_s")) sl.start_time = r_.nonNegative(sm.at("start_s"), path + ".start_s", " s");
    if (sm.count("shape")) {
      const std::string sh = r_.text(sm.at("shape"), path + ".shape");
      if (sh != "cycloidal" && sh != "trapezoidal")
        r_.fail(sm.at("shape").Mark(), path + ".shape: unknown shape '" + sh + "' (known: cycloidal, trapezoidal)");
      sl.trapezoidal = sh == "trapezoidal";
    }
    if (sm.count("max_rate_deg_s")) sl.max_rate = r_.positive(sm.at("max_rate_deg_s"), path + ".max_rate_deg_s", " deg/s") * kDegToRad;
    if (sm.count("max_acceleration_deg_s2"))
      sl.max_acceleration = r_.positive(sm.at("max_acceleration_deg_s2"), path + ".max_acceleration_deg_s2", " deg/s^2") * kDegToRad;
    return sl;
  }

  /// base.gimbal: {yaw|pitch|roll: {angle_deg, slew, range_deg, torque_capacity}, ring_mass, ring_inertia}.
  /// A commanded angle or a slew's end beyond the axis's range is an error at its line.
  GimbalSpec readGimbal(const YAML::Node& n) {
    auto m = r_.mapping(n, "base.gimbal", {"yaw", "pitch", "roll", "ring_mass", "ring_inertia"});
    GimbalSpec g;
    for (auto [name, axis] : {std::pair<const char*, GimbalAxisSpec*>{"yaw", &g.yaw}, {"pitch", &g.pitch}, {"roll", &g.roll}}) {
      if (!m.count(name)) continue;
      const std::string path = std::string("base.gimbal.") + name;
      const YAML::Node& an = m.at(name);
      auto am = r_.mapping(an, path, {"angle_deg", "slew", "range_deg", "torque_capacity"});
      if (am.count("range_deg")) axis->range = r_.positive(am.at("range_deg"), path + ".range_deg", " deg") * kDegToRad;
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
        axis->slew = readSlew(am.at("slew"), path + ".slew");
        within(am.at("slew")["to_deg"], axis->slew->to, path + ".slew.to_deg");
      }
    }
    if (m.count("ring_mass")) g.ring_mass = r_.positive(m.at("ring_mass"), "base.gimbal.ring_mass", " kg");
    if (m.count("ring_inertia")) g.ring_inertia = r_.positive(m.at("ring_inertia"), "base.gimbal.ring_inertia", " kg*m^2");
    return g;
  }

  void readBase(const YAML::Node& n, BaseSpec& b) {
    auto m = r_.mapping(n, "base", {"type", "position", "direction_deg", "table_mass", "motion", "gimbal"});
    if (m.count("type")) {
      const std::string t = r_.text(m.at("type"), "base.type");
      if (t == "table") b.type = BaseType::Table;
      else if (t != "fixed") r_.fail(m.at("type").Mark(), "base.type: unknown base type '" + t + "' (known: fixed, table)");
    }
    for (const char* k : {"table_mass", "motion"})
      if (m.count(k) && b.type != BaseType::Table) r_.fail(m.at(k).Mark(), std::string("base.") + k + " applies only with type: table");
    if (m.count("table_mass")) b.table_mass = r_.positive(m.at("table_mass"), "base.table_mass", " kg");
    if (m.count("motion")) b.motion = readTableMotion(m.at("motion"), "base.motion", {});
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

  void readJoints(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "joints");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& jn = n[i];
      const std::string path = "joints[" + std::to_string(i) + "]";
      auto m = r_.mapping(jn, path, {"name", "parent", "angle_deg", "hold", "servo_stiffness", "torquer", "slew",
                                     "torque_capacity", "torque"});
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
      if (m.count("torquer")) j.torquer = readLumpedMass(r_, m.at("torquer"), path + ".torquer");
      if (m.count("torque_capacity"))
        j.torque_capacity = r_.positive(m.at("torque_capacity"), path + ".torque_capacity", " N*m");
      if (m.count("slew")) {
        const YAML::Node& sn = m.at("slew");
        if (j.hold != JointHold::Locked)
          r_.fail(sn.Mark(), path + ".slew: only a locked joint (its torquer holding the angle) follows a slew");
        j.slew = readSlew(sn, path + ".slew");
      }
      if (m.count("torque")) {
        const YAML::Node& tn = m.at("torque");
        if (j.hold == JointHold::Locked)
          r_.fail(tn.Mark(), path + ".torque: a commanded torque needs a joint that moves (hold: free or servo)");
        j.torque_input = readTableMotion(tn, path + ".torque", {}, " N*m");
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
                                     "mount_angle_deg", "tip_mass", "branches"});
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
        if (!seg.IsScalar()) r_.fail(seg.Mark(), path + ".segments must be an integer >= 1 or 'rigid' (got " + Reader::show(seg) + ")");
        char* end = nullptr;
        const long v = std::strtol(seg.Scalar().c_str(), &end, 10);
        if (*end != '\0' || end == seg.Scalar().c_str() || v < 1 || v > 100000)
          r_.fail(seg.Mark(), path + ".segments must be an integer >= 1 or 'rigid' (got " + seg.Scalar() + ")");
        l.segments = static_cast<int>(v);
      }
      if (m.count("mount_angle_deg")) l.mount_angle = r_.number(m.at("mount_angle_deg"), path + ".mount_angle_deg") * kDegToRad;
      if (m.count("tip_mass")) l.tip_mass = readLumpedMass(r_, m.at("tip_mass"), path + ".tip_mass");

      int count = 1;
      double spread = 0;
      if (m.count("branches")) {
        const YAML::Node& bn = m.at("branches");
        auto bm = r_.mapping(bn, path + ".branches", {"count", "angle_deg"});
        const YAML::Node& c = r_.require(bm, bn, path + ".branches", "count");
        count = r_.integer(c, path + ".branches.count");
        if (count < 1 || count > 26) r_.fail(c.Mark(), path + ".branches.count must be 1 to 26 (got " + c.Scalar() + ")");
        if (count > 1) spread = r_.number(r_.require(bm, bn, path + ".branches", "angle_deg"), path + ".branches.angle_deg") * kDegToRad;
      }
      for (int k = 0; k < count; ++k) {
        LinkSpec b = l;
        if (count > 1) {
          b.name = l.name + static_cast<char>('a' + k);
          b.mount_angle += -0.5 * spread + spread * k / (count - 1);
        }
        checkName(name, path + ".name", b.name);
        link_marks_[b.name] = {ln.Mark(), path};
        a.links.push_back(b);
      }
    }
  }

  std::string where(const YAML::Node& n) const { return r_.position(n.Mark()); }

  /// A named point of the article; the message says how points are named.
  std::string point(const YAML::Node& n, const std::string& path, const ArticleSpec& a) {
    const std::string name = r_.text(n, path);
    const auto names = articlePointNames(a);
    if (std::find(names.begin(), names.end(), name) == names.end())
      r_.fail(n.Mark(), path + ": unknown point '" + name +
                            "' (points are <joint>, <link>.root, <link>.tip and <link>.h1 .. <link>.h<segments>)");
    return name;
  }

  void readClosures(const YAML::Node& n, ArticleSpec& a) {
    const std::size_t count = r_.sequence(n, "closures");
    for (std::size_t i = 0; i < count; ++i) {
      const YAML::Node& cn = n[i];
      const std::string path = "closures[" + std::to_string(i) + "]";
      auto m = r_.mapping(cn, path, {"name", "point", "to", "type", "at", "direction_deg"});
      ClosureSpec c;
      c.name = m.count("name") ? r_.text(m.at("name"), path + ".name") : "closure" + std::to_string(i + 1);
      c.point = point(r_.require(m, cn, path, "point"), path + ".point", a);
      if (m.count("to") && r_.text(m.at("to"), path + ".to") != "ground") {
        c.to = point(m.at("to"), path + ".to", a);
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
      c.where = where(cn);
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
      l.point = point(r_.require(m, ln, path, "point"), path + ".point", a);
      const YAML::Node& f = r_.require(m, ln, path, "force");
      l.force = r_.vec3(f, path + ".force");
      if (l.force[2] != 0.0)
        r_.fail(f[2].Mark(), path + ".force[2] must be 0 N: the article moves in the x-y plane (got " + f[2].Scalar() + ")");
      l.where = where(ln);
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

  const Reader& r_;
  std::set<std::string> names_;
  std::map<std::string, Located> joint_marks_, joint_parent_marks_, link_marks_;
};

}  // namespace

Scene parseScene(const std::string& yaml_text, const std::string& source_name) {
  Reader reader(source_name);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    reader.fail(e.mark, "malformed YAML: " + e.msg);
  }
  SceneParser parser(reader);
  return parser.parse(root, source_name);
}

Scene loadSceneFile(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneFileError(path + ": is a directory, not a scene file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneFileError(path + ": cannot open scene file");
  std::ostringstream os;
  os << in.rdbuf();
  if (in.bad()) throw SceneFileError(path + ": cannot read scene file");
  return parseScene(os.str(), path);
}

Scene loadDefaultScene() { return parseScene(defaultSceneYaml(), "<default scene>"); }

void overrideSegments(Scene& scene, int n) {
  for (auto& l : scene.article.links)
    if (!l.rigid) l.segments = n;
}

}  // namespace mmv

#pragma once
// Internal to sim/scene: the YAML reading primitives every section reader shares, and
// the section readers (one file per section: read_article, read_programs,
// read_simulation, read_hamsas). yaml-cpp accepts duplicate keys silently and reports
// missing keys without a position, so keys are checked here against the nodes' marks.

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "facility/lab.hpp"
#include "sim/core/text.hpp"
#include "sim/core/units.hpp"
#include "sim/scene/scene.hpp"

namespace mmv::scene_detail {

/// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);

/// Reads one document; knows the file name for messages.
class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}
  const std::string& file() const { return file_; }

  /// Patched values (`--set KEY=VALUE`, a dedicated option's) are parsed from lines at
  /// and after `first_line` (beyond the file's own): a mark there is the patch
  /// `labels[line - first_line]` ("--set KEY=VALUE", "--segments 0"); labels from
  /// `first_option` on are options, whose errors are UsageErrors.
  void setOverrides(int first_line, std::vector<std::string> labels, std::size_t first_option) {
    override_line_ = first_line;
    override_labels_ = std::move(labels);
    first_option_ = first_option;
  }

  /// "file:line:col", or the patch's label for a value that came from the command line
  /// or a front end's option; an empty document has a null mark (-1): the start of the file.
  std::string position(const YAML::Mark& mark) const {
    if (const int k = patchIndex(mark); k >= 0) return override_labels_[static_cast<std::size_t>(k)];
    std::ostringstream os;
    os << file_ << ':' << std::max(mark.line, 0) + 1 << ':' << std::max(mark.column, 0) + 1;
    return os.str();
  }

  /// Every key read so far, with its position (SourceMap).
  SourceMap sourceMap() const { return SourceMap{file_, positions_}; }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const {
    if (const int k = patchIndex(mark); k >= 0 && static_cast<std::size_t>(k) >= first_option_)
      throw UsageError(position(mark) + ": " + what);
    throw SceneError(position(mark) + ": " + what);
  }

  static std::string show(const YAML::Node& n) {
    if (n.IsScalar()) return n.Scalar();
    if (n.IsSequence()) return "a list";
    if (n.IsMap()) return "a mapping";
    return "nothing";
  }

  static constexpr double kMinMagnitude = 1e-20, kMaxMagnitude = 1e20;  ///< of any scene number (SI)

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
    // Every quantity of a lab article lies well inside 1e-20 .. 1e20 in SI units (the
    // stiffest extreme tested, E = 1e20 Pa, included). Beyond it, the products the model
    // forms (m*L^2, rho*A, E*I/h, and their squares in norms) overflow or underflow to
    // inf, NaN or 0 deep inside a solver instead of failing here.
    if (v != 0 && !(std::abs(v) >= kMinMagnitude && std::abs(v) <= kMaxMagnitude))
      fail(n.Mark(), path + " must be 0 or between 1e-20 and 1e20 in magnitude (got " + s + ")");
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
    if (!isValidUtf8(n.Scalar())) fail(n.Mark(), path + " must be UTF-8 text (got " + printable(n.Scalar()) + ")");
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
      // A copy: `it->first` lives in a temporary proxy that dies with this statement
      // (AddressSanitizer's stack-use-after-scope when a reference is kept).
      const YAML::Node key = it->first;
      if (!key.IsScalar()) fail(key.Mark(), path + ": keys must be text");
      const std::string k = key.Scalar();
      if (!isValidUtf8(k))
        fail(key.Mark(), (path.empty() ? std::string("scene") : path) + ": keys must be UTF-8 text (got " + printable(k) + ")");
      const std::string where = path.empty() ? k : path + "." + k;
      if (out.count(k)) fail(key.Mark(), "duplicate key '" + where + "'");
      bool ok = false;
      for (const auto& a : allowed) ok = ok || a == k;
      if (!ok)
        fail(key.Mark(), "unknown key '" + where + "'" + didYouMean(k, allowed) + " (allowed: " + joinNames(allowed) + ")");
      out.emplace(k, it->second);
      positions_.emplace(where, position(key.Mark()));
    }
    if (!path.empty()) positions_.emplace(path, position(n.Mark()));
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
    fail(value.Mark(), path + ": unknown " + what + " '" + name + "'" + didYouMean(name, names) + " (known: " + joinNames(names) + ")");
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
  /// Which patch a mark is in; -1: the file's own text.
  int patchIndex(const YAML::Mark& mark) const {
    const int k = mark.line - override_line_;
    return !override_labels_.empty() && k >= 0 && k < static_cast<int>(override_labels_.size()) ? k : -1;
  }

  std::string file_;
  int override_line_ = -1;
  std::vector<std::string> override_labels_;
  std::size_t first_option_ = 0;
  mutable std::map<std::string, std::string> positions_;  // filled by mapping(): what the reader has seen
};

struct Located {
  YAML::Mark mark;
  std::string path;
};

// Section readers. Each throws SceneError at the offending key's line and column.
ArticleScene readArticleScene(const YamlReader& r, const YAML::Node& root, const std::string& source);
HamsasScene readHamsasScene(const YamlReader& r, const YAML::Node& root, const std::string& source);
/// A table (or ground, or joint torque) program; `extra` keys are allowed and left to the caller.
TableMotion readTableMotion(const YamlReader& r, const YAML::Node& mn, const std::string& path,
                            const std::vector<std::string>& extra, const std::string& unit = " m");
SlewSpec readSlew(const YamlReader& r, const YAML::Node& sn, const std::string& path);
SimulationSpec readSimulation(const YamlReader& r, const YAML::Node& n, bool article);
DampingSpec readDamping(const YamlReader& r, const YAML::Node& n);
/// sections.NAME and materials.NAME (sim/scene/read_section.cpp).
Section readSection(const YamlReader& r, const std::string& name, const YAML::Node& n, const std::string& path);
Material readMaterial(const YamlReader& r, const std::string& name, const YAML::Node& n, const std::string& path);
/// `strength: {yield_factor, ultimate_factor}` (each >= 1; article/article_spec.hpp).
StrengthFactors readStrengthFactors(const YamlReader& r, const YAML::Node& n);
facility::LabSpec readLab(const YamlReader& r, const YAML::Node& n);
/// shaker: {at: STATION | auto, direction: [x, y, z] | auto, force_limit_n, stroke_m,
/// armature_mass_kg, crest_factor}; after the links and the model are read.
ShakerSceneSpec readShaker(const YamlReader& r, const YAML::Node& n, const ArticleSpec& article);
/// views: {NAME: {eye: [x, y, z], target: [x, y, z], up: [x, y, z], fov_deg: F}} (sim/scene/read_lab.cpp).
void readViews(const YamlReader& r, const YAML::Node& n, ArticleScene& scene);
/// Every key of a name->item mapping (each allowed; duplicates are still caught).
std::vector<std::string> namesOf(const YamlReader& r, const YAML::Node& n, const std::string& path);
/// "an encoder", "a rate_gyro", "an accelerometer": a sensor type in a sentence.
inline std::string withArticle(const std::string& type) {
  return (type.empty() || std::string("aeiou").find(type[0]) == std::string::npos ? "a " : "an ") + type;
}
/// sensors: [...] (sim/scene/read_simulation.cpp), after `instruments:`; their masses
/// welded on the links (weldSensorMasses).
void readSensors(const YamlReader& r, const YAML::Node& n, ArticleScene& scene);
/// instruments: {NAME: {type, mass_kg, size_m, axes, range, resolution, band_hz}}: the
/// catalogue, the report's three first (sim/scene/read_instruments.cpp).
void readInstruments(const YamlReader& r, const YAML::Node& n, ArticleScene& scene);
/// Each sensor's instrument's mass (a triaxial block's once per point) as a station mass
/// of its link; a massive sensor off the links (a joint, a hinge) is refused at its entry
/// in `sensors` (`n`).
void weldSensorMasses(const YamlReader& r, const YAML::Node& n, ArticleScene& scene);
/// A named point of the article; the message says how points are named.
std::string readPoint(const YamlReader& r, const YAML::Node& n, const std::string& path, const ArticleSpec& a);
/// The same, or a station (sim/scene/stations.hpp): where sensors go.
std::string readPointOrStation(const YamlReader& r, const YAML::Node& n, const std::string& path, const ArticleSpec& a);

}  // namespace mmv::scene_detail

// Scene section: the sensor catalogue (`instruments:`), and the sensors' masses welded
// on the article.
#include <algorithm>
#include <set>
#include <tuple>

#include "sim/scene/reader_util.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::scene_detail {
namespace {

const std::vector<std::string> kSensorTypes = {"encoder", "rate_gyro", "accelerometer", "strain"};

double within(const YamlReader& r, const YAML::Node& n, const std::string& path, double lo, double hi, const char* unit) {
  const double v = r.number(n, path);
  if (!(v >= lo && v <= hi))
    r.fail(n.Mark(), strf("%s must be between %g and %g%s (got %s)", path.c_str(), lo, hi, unit, n.Scalar().c_str()));
  return v;
}

/// The unit a sensor type measures in (its range and resolution are in it).
const char* measuredUnit(const std::string& type) {
  return type == "encoder" ? " rad" : type == "rate_gyro" ? " rad/s" : type == "strain" ? " m/m" : " m/s^2";
}

/// The keys of one entry over `i` (the report's instrument it starts from).
void readInstrumentKeys(const YamlReader& r, const std::map<std::string, YAML::Node>& e, const std::string& path, InstrumentSpec& i) {
  const std::string& type = i.spec.kind;
  if (e.count("mass_kg")) {
    i.mass_kg = within(r, e.at("mass_kg"), path + ".mass_kg", 0, 10, " kg");
    if (type == "encoder" && i.mass_kg > 0)
      r.fail(e.at("mass_kg").Mark(), path + ".mass_kg: an encoder reads its joint inside the torquer's housing: its mass is the "
                                            "torquer's (joints[i].torquer.mass)");
  }
  if (e.count("size_m")) i.size_m = within(r, e.at("size_m"), path + ".size_m", 0, 1, " m");
  if (e.count("axes")) {
    i.axes = r.integer(e.at("axes"), path + ".axes");
    if (i.axes != 1 && i.axes != 3) r.fail(e.at("axes").Mark(), path + ".axes must be 1 or 3 (a triaxial block; got " + e.at("axes").Scalar() + ")");
    if (i.axes == 3 && type != "accelerometer")
      r.fail(e.at("axes").Mark(), path + ".axes: a triaxial block is an accelerometer's (this instrument is " + withArticle(type) + ")");
  }
  if (e.count("range")) i.spec.range = r.positive(e.at("range"), path + ".range", measuredUnit(type));
  if (e.count("resolution")) i.spec.resolution = r.nonNegative(e.at("resolution"), path + ".resolution", measuredUnit(type));
  if (i.spec.resolution >= i.spec.range) {
    const YAML::Node& at = e.count("resolution") ? e.at("resolution") : e.at("range");
    r.fail(at.Mark(), strf("%s: the resolution (%g%s) must be below the range (%g%s)", path.c_str(), i.spec.resolution,
                           measuredUnit(type), i.spec.range, measuredUnit(type)));
  }
  if (e.count("band_hz")) {
    const YAML::Node& b = e.at("band_hz");
    if (!b.IsSequence() || b.size() != 2)
      r.fail(b.Mark(), path + ".band_hz must be [low, high] in Hz (low 0: no high-pass; got " + YamlReader::show(b) + ")");
    i.spec.low_cut_hz = within(r, b[0], path + ".band_hz[0]", 0, 1e6, " Hz");
    i.spec.high_cut_hz = within(r, b[1], path + ".band_hz[1]", 1e-6, 1e6, " Hz");
    if (i.spec.low_cut_hz >= i.spec.high_cut_hz)
      r.fail(b.Mark(), strf("%s.band_hz: the low edge (%g Hz) must be below the high edge (%g Hz)", path.c_str(), i.spec.low_cut_hz,
                            i.spec.high_cut_hz));
  }
}

}  // namespace

void readInstruments(const YamlReader& r, const YAML::Node& n, ArticleScene& scene) {
  scene.instruments = reportInstruments();
  const std::size_t report = scene.instruments.size();
  auto m = r.mapping(n, "instruments", namesOf(r, n, "instruments"));
  for (const auto& [name, node] : m) {
    const std::string path = "instruments." + name;
    auto e = r.mapping(node, path, {"type", "mass_kg", "size_m", "axes", "range", "resolution", "band_hz"});
    const auto own = std::find_if(scene.instruments.begin(), scene.instruments.begin() + static_cast<std::ptrdiff_t>(report),
                                  [&](const InstrumentSpec& i) { return i.name == name; });
    InstrumentSpec i;
    if (own != scene.instruments.begin() + static_cast<std::ptrdiff_t>(report)) {
      i = *own;  // the report's, its keys overridden
      if (e.count("type") && r.text(e.at("type"), path + ".type") != name)
        r.fail(e.at("type").Mark(), path + ".type: the report's " + name + " stays " + withArticle(name) + " (got " +
                                        e.at("type").Scalar() + "): give another instrument its own name");
    } else {
      const YAML::Node& tn = r.require(e, node, path, "type");
      const std::string type = r.text(tn, path + ".type");
      if (std::find(kSensorTypes.begin(), kSensorTypes.end(), type) == kSensorTypes.end())
        r.fail(tn.Mark(), path + ".type: unknown sensor type '" + type + "'" + didYouMean(type, kSensorTypes) + " (known: " +
                              joinNames(kSensorTypes) + ")");
      for (const InstrumentSpec& base : reportInstruments())  // the report's of its type as built in, then its own keys
        if (base.name == type) i = base;
      i.name = name;
    }
    readInstrumentKeys(r, e, path, i);
    i.where = r.position(node.Mark());
    if (own != scene.instruments.begin() + static_cast<std::ptrdiff_t>(report)) *own = i;
    else scene.instruments.push_back(i);
  }
}

void weldSensorMasses(const YamlReader& r, const YAML::Node& n, ArticleScene& scene) {
  std::set<std::tuple<std::string, std::string, double>> blocks;  // a triaxial block's housing, once per point
  for (std::size_t k = 0; k < scene.sensors.size(); ++k) {
    const SensorSceneSpec& s = scene.sensors[k];
    const InstrumentSpec& i = instrumentOf(scene, s);
    if (i.mass_kg == 0) continue;
    std::string why;
    auto at = pointAlongLink(scene.article, s.target, why);
    if (at && !s.span_end.empty()) at->second += 0.5 * s.span_m;  // a film's mass at its span's middle
    if (!at)
      r.fail(n[k].Mark(), "sensors[" + std::to_string(k) + "] (" + s.name + "): its instrument " + i.name + " weighs " +
                              strf("%g", i.mass_kg) + " kg, welded on the article where it sits, and " + why);
    if (i.axes == 3 && !blocks.insert({i.name, at->first, at->second}).second) continue;
    auto link = std::find_if(scene.article.links.begin(), scene.article.links.end(), [&](const LinkSpec& l) { return l.name == at->first; });
    link->station_masses.push_back({at->second, i.mass_kg});
  }
}

}  // namespace mmv::scene_detail

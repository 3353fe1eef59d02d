#include "sim/scene/scene.hpp"

#include <algorithm>

#include "sim/core/integrators.hpp"

namespace mmv {

std::string SourceMap::where(const std::string& key) const {
  for (std::string k = key; !k.empty();) {
    if (auto it = at.find(k); it != at.end()) return it->second;
    const auto cut = k.find_last_of(".[");
    k = cut == std::string::npos ? std::string() : k.substr(0, cut);
  }
  return file + ":1:1";
}

std::vector<InstrumentSpec> reportInstruments() {
  std::vector<InstrumentSpec> out;
  for (const facility::SensorSpec& spec :
       {facility::encoderSpec(), facility::rateGyroSpec(), facility::accelerometerSpec(), facility::strainSpec()}) {
    InstrumentSpec i;
    i.name = spec.kind;
    i.spec = spec;
    out.push_back(i);
  }
  return out;
}

InstrumentSpec reportInstrument(const std::string& type) {
  for (const InstrumentSpec& i : reportInstruments())
    if (i.name == type) return i;
  MMV_DEMAND(!"a sensor type");
  return {};
}

const InstrumentSpec* findInstrument(const ArticleScene& scene, const std::string& name) {
  for (const InstrumentSpec& i : scene.instruments)
    if (i.name == name) return &i;
  static const std::vector<InstrumentSpec> report = reportInstruments();
  for (const InstrumentSpec& i : report)
    if (i.name == name) return &i;
  return nullptr;
}

const InstrumentSpec& instrumentOf(const ArticleScene& scene, const SensorSceneSpec& s) {
  const InstrumentSpec* i = findInstrument(scene, s.instrument.empty() ? s.type : s.instrument);
  MMV_DEMAND(i != nullptr && i->spec.kind == s.type);  // the reader matched them
  return *i;
}

facility::SensorSpec sensorSpecOf(const ArticleScene& scene, const SensorSceneSpec& s) {
  facility::SensorSpec spec = instrumentOf(scene, s).spec;
  spec.noise_sigma = s.noise_sigma;
  spec.seed = s.seed;
  return spec;
}

const std::string& sceneName(const Scene& scene) {
  return std::visit([](const auto& s) -> const std::string& { return s.name; }, scene);
}

const std::string& sceneSource(const Scene& scene) {
  return std::visit([](const auto& s) -> const std::string& { return s.source; }, scene);
}

const std::string& sceneText(const Scene& scene) {
  return std::visit([](const auto& s) -> const std::string& { return s.text; }, scene);
}

std::vector<std::string> overrideSegments(ArticleScene& scene, int n) {
  MMV_DEMAND(n >= 1 && n <= limits::kMaxSegments);  // the CLI checks --segments against the same range
  std::vector<std::string> notes;
  for (auto& l : scene.article.links) {
    if (l.rigid) continue;
    l.segments = n;
    if (l.modes > n)  // a link in modal coordinates keeps at most its n hinges
      notes.push_back("link " + l.name + " in " + std::to_string(n) + " segments keeps " + std::to_string(n) + " of the " +
                      std::to_string(l.modes) + " modes its `modes:` asks (a link has one hinge per segment)");
    l.modes = std::min(l.modes, n);
  }
  return notes;
}

}  // namespace mmv

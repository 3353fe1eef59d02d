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

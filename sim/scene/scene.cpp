#include "sim/scene/scene.hpp"

#include "sim/core/integrators.hpp"

namespace mmv {

const std::string& sceneName(const Scene& scene) {
  return std::visit([](const auto& s) -> const std::string& { return s.name; }, scene);
}

const std::string& sceneSource(const Scene& scene) {
  return std::visit([](const auto& s) -> const std::string& { return s.source; }, scene);
}

void overrideSegments(ArticleScene& scene, int n) {
  MMV_DEMAND(n >= 1 && n <= limits::kMaxSegments);  // the CLI checks --segments against the same range
  for (auto& l : scene.article.links)
    if (!l.rigid) l.segments = n;
}

}  // namespace mmv

// Scene files: loading (bounded, regular files only), parsing into the kind of scene
// the top-level keys say, the embedded default. Sections are read in read_*.cpp.

#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/scene/reader_util.hpp"

namespace mmv {

using scene_detail::YamlReader;

Scene parseScene(const std::string& yaml_text, const std::string& source_name) {
  YamlReader reader(source_name);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    reader.fail(e.mark, "malformed YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    reader.fail(root.Mark(), "the scene is empty (expected a mapping with 'links' and 'joints')");
  if (root.IsMap() && root["hamsas"]) {
    HamsasScene h = scene_detail::readHamsasScene(reader, root, source_name);
    h.text = yaml_text;
    return h;
  }
  ArticleScene a = scene_detail::readArticleScene(reader, root, source_name);
  a.text = yaml_text;
  return a;
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

ArticleScene loadArticleSceneFile(const std::string& path) {
  Scene s = loadSceneFile(path);
  if (auto* a = std::get_if<ArticleScene>(&s)) return std::move(*a);
  throw SceneError(path + ": is a HAM-SAS isolator scene, not an article scene");
}

HamsasScene loadHamsasSceneFile(const std::string& path) {
  Scene s = loadSceneFile(path);
  if (auto* h = std::get_if<HamsasScene>(&s)) return std::move(*h);
  throw SceneError(path + ": is an article scene, not a HAM-SAS isolator scene (top-level 'hamsas:')");
}

ArticleScene loadDefaultScene() { return std::get<ArticleScene>(parseScene(defaultSceneYaml(), "<default scene>")); }

}  // namespace mmv

// Scene files: loading (bounded, regular files only), parsing into the kind of scene
// the top-level keys say, the embedded default. Sections are read in read_*.cpp.

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/core/integrators.hpp"
#include "sim/core/files.hpp"
#include "sim/core/text.hpp"
#include "sim/scene/reader_util.hpp"

namespace mmv {

using scene_detail::YamlReader;

namespace {

/// The child of `node` named `part`: a mapping's key, or a list's item whose `name`
/// is `part` (or whose index it is). Null when there is none.
YAML::Node childOf(const YAML::Node& node, const std::string& part, std::string& known) {
  if (node.IsMap()) {
    for (auto it = node.begin(); it != node.end(); ++it) {
      const YAML::Node key = it->first;
      if (key.IsScalar() && key.Scalar() == part) return it->second;
      known += (known.empty() ? "" : ", ") + key.Scalar();
    }
    return YAML::Node(YAML::NodeType::Undefined);
  }
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      const YAML::Node item = node[i];
      const YAML::Node name = item.IsMap() ? item["name"] : YAML::Node();
      if ((name && name.IsScalar() && name.Scalar() == part) || std::to_string(i) == part) return item;
      known += (known.empty() ? "" : ", ") + (name && name.IsScalar() ? name.Scalar() : std::to_string(i));
    }
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

/// `s` as a YAML double-quoted scalar: a key part with a quote or a backslash in it
/// (`--set 'l"=x'`) stays one key instead of ending the quotes early.
std::string yamlQuoted(const std::string& s) {
  std::string q = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') q += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      q += hex;
      continue;
    }
    q += c;
  }
  return q + "\"";
}

/// Applies `--set KEY=VALUE` overrides to the document: KEY is a dotted path of
/// mapping keys and list items (by their `name`, or index); VALUE is YAML. Missing
/// keys are added (the section readers then check them as if they were in the file).
/// Each override's key and value are parsed on a line of their own after the file's
/// lines, so an error in them is reported at "--set KEY=VALUE".
void applyOverrides(YAML::Node& root, const std::vector<std::string>& sets, int first_line) {
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const std::string& set = sets[k];
    const auto eq = set.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--set " + set + ": expected KEY=VALUE, e.g. links.link1.length=2.5");
    const std::string key = set.substr(0, eq), value = set.substr(eq + 1);
    std::vector<std::string> parts;
    std::stringstream ss(key);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
    if (std::find(parts.begin(), parts.end(), "") != parts.end()) throw UsageError("--set " + set + ": an empty part in the key");
    // The deepest part of the path the document has.
    // reset(), not operator=: assigning one YAML::Node to another rewrites the first's data.
    YAML::Node node;
    node.reset(root);
    std::size_t depth = 0;
    for (; depth + 1 < parts.size(); ++depth) {
      std::string known;
      YAML::Node child;
      child.reset(childOf(node, parts[depth], known));
      if (!child.IsDefined()) {
        if (!node.IsMap())
          throw SceneError("--set " + set + ": no item '" + parts[depth] + "' (known: " + (known.empty() ? "none" : known) + ")");
        break;  // from here on the override brings its own sections
      }
      node.reset(child);
    }
    if (!node.IsMap()) throw SceneError("--set " + set + ": '" + key + "' does not name a key of a mapping");
    // The rest as one flow mapping on the override's own line: {"b": {"c": VALUE}}.
    std::string text = std::string(static_cast<std::size_t>(first_line) + k, '\n');
    for (std::size_t i = depth; i < parts.size(); ++i) text += std::string(i > depth ? "{" : "") + yamlQuoted(parts[i]) + ": ";
    text += value + std::string(parts.size() - 1 - depth, '}');
    YAML::Node doc;
    try {
      doc = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw SceneError("--set " + set + ": malformed YAML value: " + e.msg);
    }
    std::string known;
    if (childOf(node, parts[depth], known).IsDefined()) node.remove(parts[depth]);
    const auto pair = doc.begin();
    node.force_insert(pair->first, pair->second);
  }
}

}  // namespace

Scene parseScene(const std::string& yaml_text, const std::string& source_name, const std::vector<std::string>& sets) {
  YamlReader reader(source_name);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    reader.fail(e.mark, "malformed YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    reader.fail(root.Mark(), "the scene is empty (expected a mapping with 'links' and 'joints')");
  if (!sets.empty()) {
    if (!root.IsMap()) reader.fail(root.Mark(), "the scene must be a mapping of keys");
    const int first_line = static_cast<int>(std::count(yaml_text.begin(), yaml_text.end(), '\n')) + 10;
    reader.setOverrides(first_line, sets);
    auto hasHamsas = [](const YAML::Node& r) { return r.IsMap() && static_cast<bool>(r["hamsas"]); };  // const: no zombie key
    const bool isolator = hasHamsas(root);
    applyOverrides(root, sets, first_line);
    // Which kind of scene the file is (an article, or HAM-SAS by its top-level `hamsas:`)
    // is the file's to say: an override that would turn one into the other is refused
    // at the override (the reader then complained about the file's own keys instead).
    if (hasHamsas(root) != isolator)
      for (const auto& set : sets)
        if (set.rfind("hamsas", 0) == 0 && (set.size() == 6 || set[6] == '=' || set[6] == '.'))
          throw SceneError("--set " + set + ": '" + std::string(isolator ? "removing" : "adding") +
                           " hamsas' would change the scene's kind; an override changes values within " +
                           (isolator ? "the HAM-SAS scene" : "the article scene"));
  }
  if (root.IsMap() && root["hamsas"]) {
    HamsasScene h = scene_detail::readHamsasScene(reader, root, source_name);
    h.text = yaml_text;
    h.overrides = sets;
    h.positions = reader.sourceMap();
    if (!sets.empty()) h.source += overrideSuffix(sets);
    return h;
  }
  ArticleScene a = scene_detail::readArticleScene(reader, root, source_name);
  a.text = yaml_text;
  a.overrides = sets;
  a.positions = reader.sourceMap();
  if (!sets.empty()) a.source += overrideSuffix(sets);
  return a;
}

std::string overrideSuffix(const std::vector<std::string>& sets) {
  std::string out;
  for (const auto& s : sets) out += " --set " + s;
  return out;
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& sets) {
  const std::string shown = printable(path);
  if (path.empty()) throw SceneFileError("empty scene path");
  std::string text, why;
  InputFileProblem problem = InputFileProblem::None;
  if (!readInputFile(path, limits::kMaxSceneBytes, text, why, &problem)) {
    if (problem == InputFileProblem::CannotOpen) throw SceneFileError(shown + ": cannot open scene file: " + why);
    if (problem == InputFileProblem::TooLarge)
      throw SceneFileError(shown + ": " + why + "; a scene file is at most " + std::to_string(limits::kMaxSceneBytes) + " bytes");
    throw SceneFileError(shown + ": " + why + ", not a scene file");
  }
  return parseScene(text, path, sets);
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

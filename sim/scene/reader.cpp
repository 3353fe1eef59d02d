// Scene files: loading (bounded, regular files only), parsing into the kind of scene
// the top-level keys say, the embedded default. Sections are read in read_*.cpp.

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
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

/// A change to the document before it is read: `key` a dotted path of mapping keys and
/// list items (by their `name`, or index), `value` YAML; `label` is how an error in it
/// is reported ("--set KEY=VALUE", "--segments 0").
struct Patch {
  std::string key, value, label;
};

/// `--set KEY=VALUE` as a patch (a UsageError if it is not KEY=VALUE).
Patch setPatch(const std::string& set) {
  const auto eq = set.find('=');
  if (eq == std::string::npos || eq == 0) throw UsageError("--set " + set + ": expected KEY=VALUE, e.g. links.link1.length=2.5");
  return {set.substr(0, eq), set.substr(eq + 1), "--set " + set};
}

/// A whole decimal integer ("12"; not "12.0", "1e1", " 3").
bool wholeInteger(const std::string& text, long& v) {
  char* end = nullptr;
  v = std::strtol(text.c_str(), &end, 10);
  return !text.empty() && end != text.c_str() && *end == '\0';
}

/// `node`'s key `key`, or an undefined node (yaml-cpp throws on asking the kind of a
/// missing key of a const node).
YAML::Node defined(const YAML::Node& node, const std::string& key) {
  std::string known;
  return node.IsMap() ? childOf(node, key, known) : YAML::Node(YAML::NodeType::Undefined);
}

/// The patches a front end's dedicated options make (SceneFlags): every flexible link's
/// `segments` (and its `modes:` where they exceed the new hinge count, with a note),
/// `gravity`. Links the document does not spell as a list of mappings are left to the
/// reader's own messages.
std::vector<Patch> flagPatches(const YAML::Node& root, const SceneFlags& flags, std::vector<std::string>* notes) {
  std::vector<Patch> out;
  const YAML::Node links = defined(root, "links");
  if (flags.segments && links.IsDefined() && links.IsSequence()) {
    const int count = *flags.segments;
    const std::string n = std::to_string(count);
    for (std::size_t i = 0; i < links.size(); ++i) {
      const YAML::Node link = links[i], seg = defined(links[i], "segments"), modes = defined(links[i], "modes");
      if (!seg.IsDefined() || (seg.IsScalar() && seg.Scalar() == "rigid")) continue;
      const std::string at = "links." + std::to_string(i) + ".";
      out.push_back({at + "segments", n, flags.segments_label});
      long asked = 0;
      if (count >= 1 && modes.IsDefined() && modes.IsScalar() && wholeInteger(modes.Scalar(), asked) && asked > count) {
        out.push_back({at + "modes", n, flags.segments_label});
        const YAML::Node name = defined(link, "name");
        const std::string shown = name.IsDefined() && name.IsScalar() ? name.Scalar() : "links[" + std::to_string(i) + "]";
        if (notes)  // a link in modal coordinates keeps at most its n hinges
          notes->push_back("link " + shown + " in " + n + " segments keeps " + n + " of the " + std::to_string(asked) +
                           " modes its `modes:` asks (a link has one hinge per segment)");
      }
    }
  }
  if (flags.no_gravity) out.push_back({"gravity", "[0, 0, 0]", flags.gravity_label});
  return out;
}

/// Applies the patches to the document. Missing keys are added (the section readers
/// then check them as if they were in the file). Each patch's key and value are parsed
/// on a line of their own after the file's lines (`first_line` on), so an error in them
/// is reported at the patch's label.
void applyPatches(YAML::Node& root, const std::vector<Patch>& patches, int first_line) {
  for (std::size_t k = 0; k < patches.size(); ++k) {
    const Patch& p = patches[k];
    std::vector<std::string> parts;
    std::stringstream ss(p.key);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
    if (std::find(parts.begin(), parts.end(), "") != parts.end()) throw UsageError(p.label + ": an empty part in the key");
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
          throw SceneError(p.label + ": no item '" + parts[depth] + "' (known: " + (known.empty() ? "none" : known) + ")");
        break;  // from here on the override brings its own sections
      }
      node.reset(child);
    }
    if (!node.IsMap()) throw SceneError(p.label + ": '" + p.key + "' does not name a key of a mapping");
    // The rest as one flow mapping on the override's own line: {"b": {"c": VALUE}}.
    std::string text = std::string(static_cast<std::size_t>(first_line) + k, '\n');
    for (std::size_t i = depth; i < parts.size(); ++i) text += std::string(i > depth ? "{" : "") + yamlQuoted(parts[i]) + ": ";
    text += p.value + std::string(parts.size() - 1 - depth, '}');
    YAML::Node doc;
    try {
      doc = YAML::Load(text);
    } catch (const YAML::ParserException& e) {
      throw SceneError(p.label + ": malformed YAML value: " + e.msg);
    }
    std::string known;
    if (childOf(node, parts[depth], known).IsDefined()) node.remove(parts[depth]);
    const auto pair = doc.begin();
    node.force_insert(pair->first, pair->second);
  }
}

}  // namespace

Scene parseScene(const std::string& yaml_text, const std::string& source_name, const std::vector<std::string>& sets,
                 const SceneFlags& flags, std::vector<std::string>* notes) {
  YamlReader reader(source_name);
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException& e) {
    reader.fail(e.mark, "malformed YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    reader.fail(root.Mark(), "the scene is empty (expected a mapping with 'links' and 'joints')");
  auto hasHamsas = [](const YAML::Node& r) { return r.IsMap() && static_cast<bool>(r["hamsas"]); };  // const: no zombie key
  const bool isolator = hasHamsas(root);
  const bool options = flags.segments || flags.no_gravity;
  if (isolator && options)
    throw UsageError((flags.segments ? flags.segments_label : flags.gravity_label) +
                     ": does not apply to a HAM-SAS scene (rigid bodies; its preloads are gravity's)");
  if (!sets.empty() || options) {
    if (!root.IsMap()) reader.fail(root.Mark(), "the scene must be a mapping of keys");
    // The patches' values are read from lines after the file's own, each its own line.
    const int first_line = static_cast<int>(std::count(yaml_text.begin(), yaml_text.end(), '\n')) + 10;
    std::vector<Patch> patches;
    for (const auto& set : sets) patches.push_back(setPatch(set));
    applyPatches(root, patches, first_line);
    // Which kind of scene the file is (an article, or HAM-SAS by its top-level `hamsas:`)
    // is the file's to say: an override that would turn one into the other is refused
    // at the override (the reader then complained about the file's own keys instead).
    if (hasHamsas(root) != isolator)
      for (const auto& set : sets)
        if (set.rfind("hamsas", 0) == 0 && (set.size() == 6 || set[6] == '=' || set[6] == '.'))
          throw SceneError("--set " + set + ": '" + std::string(isolator ? "removing" : "adding") +
                           " hamsas' would change the scene's kind; an override changes values within " +
                           (isolator ? "the HAM-SAS scene" : "the article scene"));
    // The options after the --set patches: `--set links.link1.segments=8 --segments 16` is 16.
    const std::vector<Patch> option_patches = flagPatches(root, flags, notes);
    applyPatches(root, option_patches, first_line + static_cast<int>(patches.size()));
    std::vector<std::string> labels;
    for (const auto& p : patches) labels.push_back(p.label);
    for (const auto& p : option_patches) labels.push_back(p.label);
    reader.setOverrides(first_line, labels, patches.size());
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

SceneValue sceneValueAt(const std::string& yaml_text, const std::vector<std::string>& sets, const std::string& key) {
  SceneValue v;
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::ParserException&) {
    return v;  // the reader names the file's own error
  }
  if (!root.IsMap()) return v;
  const int first_line = static_cast<int>(std::count(yaml_text.begin(), yaml_text.end(), '\n')) + 10;
  std::vector<Patch> patches;
  for (const auto& set : sets) patches.push_back(setPatch(set));
  applyPatches(root, patches, first_line);
  YAML::Node node;
  node.reset(root);
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) {
    std::string known;
    YAML::Node child;
    child.reset(part.empty() ? YAML::Node(YAML::NodeType::Undefined) : childOf(node, part, known));
    if (!child.IsDefined()) return v;
    node.reset(child);
  }
  if (!node.IsScalar()) return v;
  v.found = true;
  v.text = node.Scalar();
  char* end = nullptr;
  v.value = std::strtod(v.text.c_str(), &end);
  v.number = !v.text.empty() && *end == '\0' && std::isfinite(v.value);
  const YAML::Mark m = node.Mark();
  v.in_file = m.line >= 0 && m.line < first_line - 9;
  if (v.in_file) {
    v.line = m.line + 1, v.column = m.column + 1, v.offset = static_cast<std::size_t>(m.pos);
    std::size_t e = v.offset;
    while (e < yaml_text.size() && std::strchr(" \t\r\n,]}#", yaml_text[e]) == nullptr) ++e;
    v.length = e - v.offset;
    v.plain = yaml_text.compare(v.offset, v.length, v.text) == 0;  // not quoted, not a block scalar
  }
  return v;
}

std::string editedSceneText(const std::string& yaml_text, std::vector<SceneEdit> edits) {
  std::sort(edits.begin(), edits.end(), [](const SceneEdit& a, const SceneEdit& b) { return a.offset > b.offset; });
  std::string out = yaml_text;
  for (const auto& e : edits) {  // from the end: earlier offsets stay valid
    MMV_DEMAND(e.offset + e.length <= out.size());
    std::size_t eol = out.find('\n', e.offset);
    if (eol == std::string::npos) eol = out.size();
    if (!e.comment.empty()) out.insert(eol, "  # " + e.comment);
    out.replace(e.offset, e.length, e.value);
  }
  return out;
}

std::string overrideSuffix(const std::vector<std::string>& sets) {
  std::string out;
  for (const auto& s : sets) out += " --set " + s;
  return out;
}

Scene loadSceneFile(const std::string& path, const std::vector<std::string>& sets, const SceneFlags& flags,
                    std::vector<std::string>* notes) {
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
  return parseScene(text, path, sets, flags, notes);
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

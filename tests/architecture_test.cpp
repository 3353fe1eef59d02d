// The layering of docs/architecture.md, checked on the source tree: no #include
// points up or sideways, no file in sim/ grows past 500 lines and no function past 80.
// A rule here is the rule in the docs; change both together.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

/// Which folders each folder may include (besides itself). Lower layers first.
const std::map<std::string, std::set<std::string>>& allowedIncludes() {
  static const std::set<std::string> data{"article", "facility"};
  auto with = [](std::set<std::string> a, const std::set<std::string>& b) {
    a.insert(b.begin(), b.end());
    return a;
  };
  static const std::set<std::string> core = {};
  static const std::set<std::string> scene = with(data, {"sim/core"});
  static const std::set<std::string> model = with(scene, {"sim/scene"});
  static const std::set<std::string> statics = with(model, {"sim/model"});
  static const std::set<std::string> modes = with(statics, {"sim/statics"});
  static const std::set<std::string> linear = with(modes, {"sim/modes"});
  static const std::set<std::string> time = with(statics, {"sim/statics"});
  static const std::set<std::string> hamsas = with(with(linear, time), {"sim/linear", "sim/time"});
  static const std::set<std::string> plan = with(hamsas, {"sim/hamsas"});
  static const std::set<std::string> io = with(plan, {"sim/plan"});
  static const std::set<std::string> view = io;  // beside sim/io: neither includes the other
  static const std::set<std::string> app = with(io, {"sim/io"});
  static const std::set<std::string> cli = with(app, {"sim/app", "renders", "sim/view"});
  static const std::map<std::string, std::set<std::string>> rules{
      {"article", {}},           {"facility", {}},          {"sim/core", core},   {"sim/scene", scene},
      {"sim/model", model},      {"sim/statics", statics},  {"sim/modes", modes}, {"sim/linear", linear},
      {"sim/time", time},        {"sim/hamsas", hamsas},    {"sim/plan", plan},       {"sim/io", io},       {"sim/view", view},  {"renders", {"sim/core"}},
      {"sim/app", app},          {"sim/cli", cli},          {"python", with(app, {"sim/app"})},
  };
  return rules;
}

/// The folder (a key of allowedIncludes) a repository path belongs to, or "".
std::string folderOf(const std::string& path) {
  std::string best;
  for (const auto& [folder, _] : allowedIncludes())
    if (path.rfind(folder + "/", 0) == 0 && folder.size() > best.size()) best = folder;
  return best;
}

std::vector<fs::path> sources(const std::vector<std::string>& roots) {
  std::vector<fs::path> out;
  for (const auto& r : roots)
    for (const auto& e : fs::recursive_directory_iterator(fs::path(MMVLAB_SOURCE_DIR) / r)) {
      const auto ext = e.path().extension();
      if (e.is_regular_file() && (ext == ".cpp" || ext == ".hpp" || ext == ".in")) out.push_back(e.path());
    }
  return out;
}

std::string repoPath(const fs::path& p) { return fs::relative(p, MMVLAB_SOURCE_DIR).generic_string(); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// Every project #include of a file (quoted, with a folder).
std::vector<std::string> projectIncludes(const std::string& text) {
  static const std::regex inc(R"re(^\s*#\s*include\s+"([^"]+)")re");
  std::vector<std::string> out;
  std::istringstream is(text);
  std::string line;
  std::smatch m;
  while (std::getline(is, line))
    if (std::regex_search(line, m, inc)) out.push_back(m[1]);
  return out;
}

/// A violation of the layering in `path`, or "" (exposed for the self-test).
std::vector<std::string> layeringViolations(const std::string& path, const std::string& text) {
  std::vector<std::string> bad;
  const std::string from = folderOf(path);
  if (from.empty()) return bad;
  const auto& allowed = allowedIncludes().at(from);
  for (const auto& inc : projectIncludes(text)) {
    const std::string to = folderOf(inc);
    if (to.empty() || to == from || allowed.count(to)) continue;
    bad.push_back(path + " includes " + inc + " (" + from + " may not include " + to + ")");
  }
  return bad;
}

/// Source text without comments, string/char literals and preprocessor lines
/// (newlines kept, so line numbers hold).
std::string stripCode(const std::string& src) {
  std::string out;
  const std::size_t n = src.size();
  bool line_start = true;
  for (std::size_t i = 0; i < n;) {
    const char c = src[i];
    if (line_start) {
      std::size_t j = i;
      while (j < n && (src[j] == ' ' || src[j] == '\t')) ++j;
      if (j < n && src[j] == '#') {  // preprocessor line (with continuations)
        while (j < n && !(src[j] == '\n' && src[j - 1] != '\\')) ++j;
        i = j;
        continue;
      }
    }
    line_start = c == '\n';
    if (src.compare(i, 2, "//") == 0) {
      while (i < n && src[i] != '\n') ++i;
      continue;
    }
    if (src.compare(i, 2, "/*") == 0) {
      const std::size_t j = src.find("*/", i + 2);
      const std::size_t end = j == std::string::npos ? n : j + 2;
      for (std::size_t k = i; k < end; ++k)
        if (src[k] == '\n') out += '\n';
      i = end;
      continue;
    }
    if (c == 'R' && i + 1 < n && src[i + 1] == '"') {  // raw string R"d(...)d"
      const std::size_t open = src.find('(', i);
      const std::string delim = ")" + src.substr(i + 2, open - i - 2) + "\"";
      const std::size_t j = src.find(delim, open);
      const std::size_t end = j == std::string::npos ? n : j + delim.size();
      out += "\"\"";
      for (std::size_t k = i; k < end; ++k)
        if (src[k] == '\n') out += '\n';
      i = end;
      continue;
    }
    if (c == '"' || (c == '\'' && !(i > 0 && std::isxdigit(static_cast<unsigned char>(src[i - 1]))))) {
      std::size_t j = i + 1;
      while (j < n && src[j] != c) j += src[j] == '\\' ? 2 : 1;
      out += c;
      out += c;
      i = j + 1;
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

struct LongFunction {
  int first_line = 0, lines = 0;
};

/// Function bodies longer than `max_lines` (lambdas count with their function).
std::vector<LongFunction> longFunctions(const std::string& source, int max_lines) {
  static const std::regex ns(R"(^(namespace\b.*|extern\s+""\s*|)$)");
  static const std::regex type(R"(\b(class|struct|union|enum)\b[^()]*$)");
  static const std::regex control(R"(^(if|for|while|switch|catch|do|else|try)\b)");
  const std::string s = stripCode(source);
  enum Kind { kScope, kType, kFunction, kBlock };
  std::vector<std::pair<Kind, int>> stack;
  std::vector<LongFunction> out;
  std::string stmt;
  int line = 1;
  for (char ch : s) {
    if (ch == '\n') ++line;
    if (ch == '{') {
      std::string t = stmt;
      t.erase(0, t.find_first_not_of(" \t\n"));
      t.erase(t.find_last_not_of(" \t\n") + 1);
      Kind kind = kBlock;
      bool top = true;
      for (const auto& [k, _] : stack) top = top && (k == kScope || k == kType);
      if (top) {
        if (std::regex_match(t, ns)) kind = kScope;
        else if (std::regex_search(t, type)) kind = kType;
        else if (t.find(')') != std::string::npos && !std::regex_search(t, control) &&
                 t.substr(0, t.find('(')).find('=') == std::string::npos)
          kind = kFunction;
      }
      stack.push_back({kind, line});
      stmt.clear();
    } else if (ch == '}') {
      if (!stack.empty()) {
        const auto [k, first] = stack.back();
        stack.pop_back();
        if (k == kFunction && line - first + 1 > max_lines) out.push_back({first, line - first + 1});
      }
      stmt.clear();
    } else if (ch == ';') {
      stmt.clear();
    } else {
      stmt += ch;
    }
  }
  return out;
}

/// User input is checked once, at the boundary (docs/architecture.md, "Checked once"):
/// below the studies nothing throws a plain UsageError (an analysis that finds a request
/// it cannot meet throws OptionError, which each front end names its own way) and
/// nothing parses text, except where named here, each with its reason.
const std::map<std::string, std::string>& boundaryFiles() {
  static const std::map<std::string, std::string> files = {
      {"sim/core/errors.hpp", "defines UsageError and OptionError"},
      {"sim/scene/reader.cpp", "the scene reader: every patch (--set, Python's set=) is checked here with its key"},
      {"sim/scene/reader_util.hpp", "the scene reader: a dedicated option's patch (--segments) fails as a usage error"},
  };
  return files;
}
const std::map<std::string, std::string>& parsingFiles() {
  static const std::map<std::string, std::string> files = {
      {"sim/scene/", "the scene reader: YAML scalars with their line and column"},
      {"sim/io/uff_read.cpp", "the measured UFF reader, with line and column"},
      {"sim/io/run_dir.cpp", "reads back a run directory mmvlab wrote"},
      {"sim/io/output_dir.cpp", "reads its own staging directories' process ids"},
      {"sim/plan/design_sweep.cpp", "reads back its own journal and table"},
      {"sim/modes/place_sensors.cpp", "reads back a station name it formatted (rounding past the tip)"},
      {"facility/table_programs.cpp", "the table profile reader (a CSV file), with its line"},
      {"renders/frame_memory.cpp", "reads /proc/meminfo"},
  };
  return files;
}

bool listed(const std::map<std::string, std::string>& files, const std::string& path) {
  for (const auto& f : files)
    if (path == f.first || (f.first.back() == '/' && path.rfind(f.first, 0) == 0)) return true;
  return false;
}

std::vector<std::string> boundaryViolations(const std::string& path, const std::string& text) {
  const std::string folder = folderOf(path);
  if (folder == "sim/app" || folder == "sim/cli" || folder == "python") return {};
  static const std::regex usage(R"(\bthrow\s+UsageError\b|\bUsageError\s*[({]|,\s*UsageError\s*,)");
  static const std::regex parse(R"(\bsto(i|l|ll|ul|ull|f|d|ld)\s*\(|\bstrto(d|f|l|ll|ul|ull|ld)\s*\(|\bs?scanf\s*\(|\bstd::ato(i|f|l|ll)\s*\(|\bfrom_chars\s*\()");
  std::vector<std::string> out;
  std::istringstream lines(stripCode(text));
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    const std::string at = path + ":" + std::to_string(n) + ": ";
    if (std::regex_search(line, usage) && !listed(boundaryFiles(), path))
      out.push_back(at + "a UsageError below the studies: check the option in sim/app, or throw OptionError");
    if (std::regex_search(line, parse) && !listed(parsingFiles(), path))
      out.push_back(at + "parses text below the studies: parse it at the boundary (sim/app, the readers)");
  }
  return out;
}

TEST(Architecture, UserInputIsCheckedOnceAtTheBoundary) {
  for (const auto& p : sources({"article", "facility", "sim", "renders"}))
    for (const auto& v : boundaryViolations(repoPath(p), slurp(p))) ADD_FAILURE() << v;
}

TEST(Architecture, NoIncludePointsUp) {
  std::vector<std::string> bad;
  for (const auto& p : sources({"article", "facility", "sim", "renders", "python"})) {
    const auto v = layeringViolations(repoPath(p), slurp(p));
    bad.insert(bad.end(), v.begin(), v.end());
  }
  for (const auto& b : bad) ADD_FAILURE() << b;
}

TEST(Architecture, PlainDataHasNoSimbody) {
  // article/, facility/, sim/core and sim/scene describe hardware and scenes as plain data.
  for (const auto& p : sources({"article", "facility", "sim/core", "sim/scene", "renders"})) {
    const std::string text = slurp(p);
    EXPECT_EQ(text.find("#include <Simbody.h>"), std::string::npos) << repoPath(p);
    EXPECT_EQ(text.find("SimTK::"), std::string::npos) << repoPath(p);
  }
}

/// sim/io holds readers and writers of plain results: a line that asks a Simbody model
/// or state for something (a computation a study owes its writers) is reported.
std::vector<std::string> writerViolations(const std::string& path, const std::string& text) {
  if (folderOf(path) != "sim/io") return {};
  static const std::regex simbody(R"(\bSimTK::|\brealize\s*\(|\bgetSystem\s*\()");
  std::vector<std::string> out;
  std::istringstream lines(stripCode(text));
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n)
    if (std::regex_search(line, simbody))
      out.push_back(path + ":" + std::to_string(n) + ": sim/io asks Simbody: compute it in the study (sim/app) or a "
                    "lower layer and hand the writer plain data");
  return out;
}

TEST(Architecture, WritersTakePlainData) {
  for (const auto& p : sources({"sim/io"}))
    for (const auto& v : writerViolations(repoPath(p), slurp(p))) ADD_FAILURE() << v;
}

TEST(Architecture, FilesAndFunctionsStaySmall) {
  for (const auto& p : sources({"sim"})) {
    const std::string text = slurp(p);
    const auto lines = std::count(text.begin(), text.end(), '\n');
    EXPECT_LE(lines, 500) << repoPath(p) << " has " << lines << " lines: it is usually two ideas";
    for (const auto& f : longFunctions(text, 80))
      ADD_FAILURE() << repoPath(p) << ":" << f.first_line << ": a function of " << f.lines << " lines (at most 80)";
  }
}

// The checks themselves must be able to fail.
TEST(Architecture, ChecksCatchWhatTheyShould) {
  EXPECT_EQ(layeringViolations("sim/statics/x.cpp", "#include \"sim/modes/modal.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("sim/scene/x.cpp", "#include \"sim/time/run_integrator.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("article/x.cpp", "#include \"sim/model/model.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("sim/io/x.cpp", "#include \"renders/plot.hpp\"\n").size(), 1u);
  EXPECT_TRUE(layeringViolations("sim/hamsas/x.cpp", "#include \"sim/time/simulation.hpp\"\n").empty());
  EXPECT_TRUE(layeringViolations("sim/cli/x.cpp", "#include \"renders/plot.hpp\"\n").empty());
  EXPECT_EQ(layeringViolations("renders/x.cpp", "#include \"sim/model/model.hpp\"\n").size(), 1u);
  EXPECT_TRUE(layeringViolations("renders/x.cpp", "#include \"sim/core/drawing.hpp\"\n").empty());
  EXPECT_EQ(layeringViolations("sim/io/x.cpp", "#include \"sim/app/study.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("sim/io/x.cpp", "#include \"sim/view/article_drawing.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("sim/view/x.cpp", "#include \"sim/io/output_dir.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("sim/app/x.cpp", "#include \"sim/view/article_drawing.hpp\"\n").size(), 1u);
  EXPECT_TRUE(layeringViolations("sim/cli/x.cpp", "#include \"sim/view/hamsas_drawing.hpp\"\n").empty());
  EXPECT_EQ(layeringViolations("python/x.cpp", "#include \"renders/plot.hpp\"\n").size(), 1u);
  EXPECT_EQ(layeringViolations("python/x.cpp", "#include \"sim/cli/commands.hpp\"\n").size(), 1u);
  EXPECT_TRUE(layeringViolations("python/x.cpp", "#include \"sim/app/study.hpp\"\n").empty());
  EXPECT_EQ(boundaryViolations("sim/modes/x.cpp", "void f() {\n  throw UsageError(\"--modes: 3\");\n}\n").size(), 1u);
  EXPECT_EQ(boundaryViolations("sim/time/x.cpp", "MMV_THROW_UNLESS(x > 0, UsageError, \"x\");\n").size(), 1u);
  EXPECT_EQ(boundaryViolations("sim/linear/x.cpp", "int n = std::stoi(text);\ndouble v = strtod(s, &e);\n").size(), 2u);
  EXPECT_EQ(boundaryViolations("sim/plan/x.cpp", "std::sscanf(v, \"%d\", &n);\nint k = std::atoi(v);\n").size(), 2u);
  EXPECT_TRUE(boundaryViolations("sim/time/x.cpp", "Impl(double a) : atol(a) {}\n").empty());  // a member named atol
  EXPECT_TRUE(boundaryViolations("sim/modes/x.cpp", "throw OptionError(\"--modes\", \": 3\");\n"
                                                    "catch (const UsageError& e) {}\n// throw UsageError(x)\n").empty());
  EXPECT_TRUE(boundaryViolations("sim/app/x.cpp", "throw UsageError(std::to_string(std::stoi(x)));\n").empty());
  EXPECT_TRUE(boundaryViolations("sim/scene/read_x.cpp", "double v = std::strtod(s, &e);\n").empty());
  EXPECT_EQ(boundaryViolations("sim/scene/read_x.cpp", "throw UsageError(\"x\");\n").size(), 1u);
  EXPECT_EQ(writerViolations("sim/io/x.cpp", "SimTK::State st = s;\nmodel.getSystem().realize(st, x);\n").size(), 2u);
  EXPECT_TRUE(writerViolations("sim/view/x.cpp", "SimTK::State st = s;\n").empty());
  EXPECT_TRUE(writerViolations("sim/io/x.cpp", "// SimTK::State in a comment\nconst char* t = \"realize(\";\n").empty());
  std::string body = "namespace a {\nint f(int x) {\n";
  for (int i = 0; i < 90; ++i) body += "  x += 1;  // }\n";
  body += "  auto g = [&]() { return \"}\"; };\n  return x;\n}\nstruct S {\n  int h() { return 1; }\n};\n}\n";
  const auto found = longFunctions(body, 80);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].first_line, 2);
  EXPECT_EQ(found[0].lines, 94);
  EXPECT_TRUE(longFunctions(body, 100).empty());
}

}  // namespace

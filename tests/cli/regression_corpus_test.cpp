// The regression corpus (tests/fuzz/regressions.txt): every input that ever broke the
// README's contract, reduced to a minimal case, run through the mmvlab executable. Each
// case must keep the contract (no signal, no internal error, no hang, exit 65 with
// file:line:col, nothing raw on stderr, no NaN/inf printed on success) and give the
// exit code and message its entry states. One test per case, named after it.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <regex>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

struct Case {
  std::string id, why, scene, run, exit = "0";
  std::vector<std::pair<std::string, std::string>> replaces, files;
  std::vector<std::string> in_stderr, not_in_stderr, in_stdout, not_in_stdout;
  int line = 0;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.id; }

/// \n, \t, \\ and \xNN in a manifest value.
std::string unescape(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '\\' || i + 1 == s.size()) {
      out += s[i];
      continue;
    }
    const char c = s[++i];
    if (c == 'n') out += '\n';
    else if (c == 't') out += '\t';
    else if (c == 'x' && i + 2 < s.size() + 1) out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16)), i += 2;
    else out += c;
  }
  return out;
}

std::pair<std::string, std::string> arrow(const std::string& v, const std::string& where) {
  const auto a = v.find(" => ");
  if (a == std::string::npos) throw std::runtime_error(where + ": expected 'OLD => NEW'");
  return {unescape(v.substr(0, a)), unescape(v.substr(a + 4))};
}

std::vector<Case> loadCases() {
  const std::string path = std::string(MMVLAB_SOURCE_DIR) + "/tests/fuzz/regressions.txt";
  std::ifstream in(path);
  std::vector<Case> cases;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    const std::string where = path + ":" + std::to_string(n);
    if (line.front() == '[' && line.back() == ']') {
      cases.push_back(Case{});
      cases.back().id = line.substr(1, line.size() - 2);
      cases.back().line = n;
      continue;
    }
    const auto colon = line.find(": ");
    if (cases.empty() || colon == std::string::npos) throw std::runtime_error(where + ": expected 'key: value'");
    const std::string k = line.substr(0, colon), v = line.substr(colon + 2);
    Case& c = cases.back();
    if (k == "why") c.why = v;
    else if (k == "scene") c.scene = v;
    else if (k == "replace") c.replaces.push_back(arrow(v, where));
    else if (k == "file") c.files.push_back(arrow(v, where));
    else if (k == "run") c.run = v;
    else if (k == "exit") c.exit = v;
    else if (k == "stderr") c.in_stderr.push_back(unescape(v));
    else if (k == "not-stderr") c.not_in_stderr.push_back(unescape(v));
    else if (k == "stdout") c.in_stdout.push_back(unescape(v));
    else if (k == "not-stdout") c.not_in_stdout.push_back(unescape(v));
    else throw std::runtime_error(where + ": unknown key '" + k + "'");
  }
  return cases;
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all = loadCases();
  return all;
}

std::string replaceAll(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
  return s;
}

/// What breaks the contract, whatever the case expects ("" when nothing does).
std::string contractBreach(int status, const std::string& out, const std::string& err) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  const int code = WEXITSTATUS(status);
  if (code == 137 || code == 124) return "did not finish within the case's time limit (a hang)";
  if (code == 70) return "internal error (exit 70) from input";
  if (code == 65 && !std::regex_search(err, std::regex(R"(:\d+:\d+: |--set )")))
    return "exit 65 without file:line:col";
  if (std::regex_search(err, std::regex("[\\x00-\\x08\\x0b-\\x1f\\x7f]"))) return "control bytes on stderr";
  if (code == 0 && std::regex_search(out, std::regex(R"((^|[^A-Za-z_])-?(nan|inf)([^A-Za-z_]|$))", std::regex::icase)))
    return "NaN or inf in the output of a successful run";
  return "";
}

class RegressionCorpus : public ::testing::TestWithParam<Case> {};

TEST_P(RegressionCorpus, KeepsTheContract) {
  const Case& c = GetParam();
  const fs::path dir = freshTestDir("mmvlab_corpus_");
  std::string scene_path;
  if (!c.scene.empty()) {
    std::string text = slurp(fs::path(MMVLAB_SOURCE_DIR) / "scenes" / c.scene);
    ASSERT_FALSE(text.empty()) << c.scene;
    for (const auto& [from, to] : c.replaces) {
      const auto at = text.find(from);
      ASSERT_NE(at, std::string::npos) << "replace: '" << from << "' is not in " << c.scene;
      text.replace(at, from.size(), to);
    }
    scene_path = (dir / c.scene).string();
    std::ofstream(scene_path, std::ios::binary) << text;
  }
  for (const auto& [name, content] : c.files) std::ofstream(dir / name, std::ios::binary) << content;
  std::string run = replaceAll(c.run, "{scene}", scene_path);
  run = replaceAll(run, "{dir}", dir.string());
  run = replaceAll(run, "{source}", MMVLAB_SOURCE_DIR);
  const std::string cmd = "cd '" + dir.string() + "' && timeout -s KILL 300 " + std::string(MMVLAB_BINARY) + " " + run +
                          " >stdout 2>stderr";
  const int status = std::system(cmd.c_str());
  const std::string out = slurp(dir / "stdout"), err = slurp(dir / "stderr");
  const std::string context = "case [" + c.id + "] (regressions.txt:" + std::to_string(c.line) + ", " + c.why +
                              ")\nmmvlab " + run + "\nstderr: " + err.substr(0, 2000);
  EXPECT_EQ(contractBreach(status, out, err), "") << context;
  ASSERT_TRUE(WIFEXITED(status)) << context;
  EXPECT_EQ(std::to_string(WEXITSTATUS(status)), c.exit) << context;
  for (const auto& s : c.in_stderr) EXPECT_NE(err.find(s), std::string::npos) << "stderr lacks '" << s << "'\n" << context;
  for (const auto& s : c.not_in_stderr) EXPECT_EQ(err.find(s), std::string::npos) << "stderr has '" << s << "'\n" << context;
  for (const auto& s : c.in_stdout) EXPECT_NE(out.find(s), std::string::npos) << "stdout lacks '" << s << "'\n" << context;
  for (const auto& s : c.not_in_stdout) EXPECT_EQ(out.find(s), std::string::npos) << "stdout has '" << s << "'\n" << context;
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Cases, RegressionCorpus, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name;
                           for (char ch : info.param.id) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                           return name;
                         });

// The corpus holds at least the issue's 70 inputs, each with its reason and command.
TEST(RegressionCorpusManifest, HoldsEveryRecordedInput) {
  EXPECT_GE(cases().size(), 70u);
  for (const auto& c : cases()) {
    EXPECT_FALSE(c.why.empty()) << c.id;
    EXPECT_FALSE(c.run.empty()) << c.id;
  }
}

}  // namespace
}  // namespace mmv::cli_testing

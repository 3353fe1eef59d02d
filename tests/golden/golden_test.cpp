// Golden outputs of the shipped scenes (tests/golden/commands.txt): the text, JSON,
// CSV and UFF a user gets must not change unless a change means them to. Text must
// match exactly; numbers must match to 1e-9 relative or one unit in the last printed
// digit (another machine's BLAS may round the last digit the other way). Wall times
// and dates are masked. Regenerate after an intended change with
//   MMVLAB_UPDATE_GOLDEN=1 build/tests/golden_tests
// and review the diff of tests/golden/expected/ before committing it.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

struct GoldenCase {
  std::string name, args;
};

void PrintTo(const GoldenCase& c, std::ostream* os) { *os << "mmvlab " << c.args; }

std::vector<GoldenCase> readCases() {
  std::ifstream in(fs::path(MMVLAB_SOURCE_DIR) / "tests/golden/commands.txt");
  std::vector<GoldenCase> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const auto bar = line.find('|');
    if (bar == std::string::npos) continue;
    cases.push_back({line.substr(0, bar), line.substr(bar + 1)});
  }
  return cases;
}

/// Masks what legitimately changes from run to run: wall times and the like.
std::string mask(std::string s) {
  static const std::regex json_time(R"re(("[^"]*(wall|seconds|elapsed|_time_s|time_ms)[^"]*"\s*:\s*)[-0-9.eE+]+)re");
  static const std::regex text_time(R"re(((wall|took|in|stepping|sampling)\s*[:=]?\s*)[0-9.]+(e[-+]?[0-9]+)?\s*(s|ms)\b)re");
  static const std::regex json_block(R"re("time_s"\s*:\s*\{[^}]*\})re");
  static const std::regex time_line(R"re((^|\n)Time: [^\n]*)re");
  static const std::regex wall(R"re([0-9.]+(e[-+]?[0-9]+)? s wall)re");
  static const std::regex uff_date(R"re(\d\d-[A-Z]{3}-\d\d \d\d:\d\d:\d\d)re");
  s = std::regex_replace(s, uff_date, "<date>");
  s = std::regex_replace(s, json_block, "\"time_s\": <time>");
  s = std::regex_replace(s, time_line, "$1Time: <time>");
  s = std::regex_replace(s, wall, "<time> s wall");
  s = std::regex_replace(s, json_time, "$1<time>");
  s = std::regex_replace(s, text_time, "$1<time>");
  return s;
}

/// Output of one case: stdout, then every text file written to --out, in name order.
std::string runCase(const GoldenCase& c, const fs::path& work) {
  fs::remove_all(work);
  fs::create_directories(work);
  std::string args = c.args;
  const fs::path out = work / "out";
  const auto at = args.find("@OUT");
  if (at != std::string::npos) args.replace(at, 4, out.string());
  const std::string cmd = "cd '" + std::string(MMVLAB_SOURCE_DIR) + "' && '" + std::string(MMVLAB_BINARY) + "' " + args +
                          " >'" + (work / "stdout").string() + "' 2>'" + (work / "stderr").string() + "'";
  const int status = std::system(cmd.c_str());
  std::ostringstream os;
  os << "=== exit " << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << "\n";
  os << "=== stdout\n" << mask(slurp(work / "stdout"));
  if (fs::exists(out)) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(out)) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      const std::string ext = f.extension().string();
      if (ext == ".png" || ext == ".mat" || ext == ".mp4" || ext == ".avi") {
        os << "=== file " << f.filename().string() << " (binary, not compared)\n";
        continue;
      }
      os << "=== file " << f.filename().string() << "\n" << mask(slurp(f));
    }
  }
  return os.str();
}

/// Splits text into alternating non-number and number tokens.
struct Tokens {
  std::vector<std::string> text;    // text[i] precedes number[i]
  std::vector<std::string> number;
};

Tokens tokenize(const std::string& s) {
  static const std::regex num(R"([-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?)");
  Tokens t;
  std::size_t last = 0;
  for (auto it = std::sregex_iterator(s.begin(), s.end(), num); it != std::sregex_iterator(); ++it) {
    t.text.push_back(s.substr(last, it->position() - last));
    t.number.push_back(it->str());
    last = it->position() + it->length();
  }
  t.text.push_back(s.substr(last));
  return t;
}

/// One unit in the last printed digit of a number token (0 for an integer without exponent).
double lastDigit(const std::string& tok) {
  const auto e = tok.find_first_of("eE");
  const std::string mant = tok.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::stoi(tok.substr(e + 1));
  const auto dot = mant.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mant.size() - dot - 1);
  return std::pow(10.0, exponent - decimals);
}

/// Empty when equal within tolerance; else the first difference, with context.
std::string compare(const std::string& expected, const std::string& actual) {
  const Tokens a = tokenize(expected), b = tokenize(actual);
  if (a.number.size() != b.number.size() || a.text != b.text) {
    // Find the first differing line for the message.
    std::istringstream ea(expected), eb(actual);
    std::string la, lb;
    int line = 0;
    while (true) {
      const bool ga = static_cast<bool>(std::getline(ea, la)), gb = static_cast<bool>(std::getline(eb, lb));
      ++line;
      if (!ga && !gb) break;
      if (tokenize(la).text != tokenize(lb).text || !ga || !gb)
        return "line " + std::to_string(line) + " differs in text:\n  expected: " + la + "\n  actual:   " + lb;
    }
    return "the number of values differs";
  }
  for (std::size_t i = 0; i < a.number.size(); ++i) {
    if (a.number[i] == b.number[i]) continue;
    const double x = std::stod(a.number[i]), y = std::stod(b.number[i]);
    const double tol = 1e-9 * std::max(std::abs(x), std::abs(y)) + 1.000001 * std::max(lastDigit(a.number[i]), lastDigit(b.number[i]));
    if (std::abs(x - y) > tol)
      return "value " + std::to_string(i) + " differs: expected " + a.number[i] + ", got " + b.number[i] + " after \"" +
             a.text[i].substr(a.text[i].size() > 60 ? a.text[i].size() - 60 : 0) + "\"";
  }
  return {};
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, OutputUnchanged) {
  const GoldenCase& c = GetParam();
  const fs::path work = fs::temp_directory_path() / ("mmvlab_golden_" + std::to_string(::getpid()) + "_" + c.name);
  const std::string actual = runCase(c, work);
  fs::remove_all(work);
  const fs::path expected_file = fs::path(MMVLAB_SOURCE_DIR) / "tests/golden/expected" / (c.name + ".txt");
  if (std::getenv("MMVLAB_UPDATE_GOLDEN")) {
    fs::create_directories(expected_file.parent_path());
    std::ofstream(expected_file, std::ios::binary) << actual;
    GTEST_SKIP() << "wrote " << expected_file;
  }
  ASSERT_TRUE(fs::exists(expected_file)) << expected_file << " missing: run with MMVLAB_UPDATE_GOLDEN=1";
  const std::string diff = compare(slurp(expected_file), actual);
  EXPECT_TRUE(diff.empty()) << "mmvlab " << c.args << "\n" << diff;
}

INSTANTIATE_TEST_SUITE_P(ShippedScenes, Golden, ::testing::ValuesIn(readCases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) { return info.param.name; });

// The comparison itself must be able to fail.
TEST(GoldenCompare, CatchesChangedTextAndNumbers) {
  EXPECT_TRUE(compare("f = 1.2345 Hz\n", "f = 1.2346 Hz\n").empty());  // one unit in the last digit
  EXPECT_FALSE(compare("f = 1.2345 Hz\n", "f = 1.2347 Hz\n").empty());
  EXPECT_FALSE(compare("f = 1.2345 Hz\n", "f = 1.2345 rad\n").empty());
  EXPECT_FALSE(compare("a 1 2\n", "a 1 2 3\n").empty());
  EXPECT_TRUE(compare("x 3.000000000000001e5\n", "x 3.0000000000000012e5\n").empty());
  EXPECT_EQ(mask("{\"wall_s\": 0.25}"), "{\"wall_s\": <time>}");
}

}  // namespace

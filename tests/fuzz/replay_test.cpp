// The fuzzers' corpus replayed by the normal suite (tests/fuzz/README.md): every input
// the scene fuzzers kept (tests/fuzz/corpus/: inputs that reached new code, merged to a
// small set, and any that once broke the contract) and every shipped scene, through
// the same targets and the same judgement as libFuzzer's runs, in the plain build.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "fuzz/fuzz_targets.hpp"
#include "sim/core/errors.hpp"

namespace mmv::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs(const std::string& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(fs::path(MMVLAB_SOURCE_DIR) / dir))
    if (e.is_regular_file()) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

TEST(FuzzReplay, ReaderKeepsTheContractOnTheCorpus) {
  std::size_t n = 0;
  for (const std::string dir : {"tests/fuzz/corpus", "scenes"})
    for (const auto& p : inputs(dir)) {
      const auto breach = readerTarget(read(p));
      EXPECT_FALSE(breach.has_value()) << p << ": " << breach.value_or("");
      ++n;
    }
  EXPECT_GE(n, 50u);  // the corpus is there
}

TEST(FuzzReplay, ModesKeepsTheContractOnTheCorpus) {
  for (const std::string dir : {"tests/fuzz/corpus", "scenes"})
    for (const auto& p : inputs(dir)) {
      const auto breach = modesTarget(read(p));
      EXPECT_FALSE(breach.has_value()) << p << ": " << breach.value_or("");
    }
}

// The other inputs' corpora (tests/fuzz/corpus-spec, -uff, -set, -rundir: the seeds
// and what their fuzzers kept) through their targets.
TEST(FuzzReplay, SpecUffSetAndRunDirectoryReadersKeepTheContractOnTheirCorpora) {
  struct Corpus {
    const char* dir;
    std::optional<std::string> (*target)(const std::string&);
  };
  for (const Corpus& c : {Corpus{"tests/fuzz/corpus-spec", specTarget}, Corpus{"sweeps", specTarget}, Corpus{"tests/fuzz/corpus-uff", uffTarget},
                          Corpus{"tests/fuzz/corpus-set", setTarget}, Corpus{"tests/fuzz/corpus-rundir", runDirTarget}}) {
    std::size_t n = 0;
    for (const auto& p : inputs(c.dir)) {
      const auto breach = c.target(read(p));
      EXPECT_FALSE(breach.has_value()) << p << ": " << breach.value_or("");
      ++n;
    }
    EXPECT_GE(n, 1u) << c.dir;
  }
}

// The new targets can fail too: an unpositioned error is a breach, a well-formed input is
// accepted, and a refused one is accepted when its message names the input.
TEST(FuzzReplay, TheOtherTargetsJudgeTheirInputs) {
  EXPECT_FALSE(specTarget("scene: x.yaml\nparameters: []\noutputs: [mass]\n").has_value());  // refused at its line
  EXPECT_FALSE(setTarget("links.link9.length=2\n").has_value());                               // refused, named --set
  EXPECT_FALSE(setTarget("links.link1.length=2.5\n").has_value());
  EXPECT_FALSE(uffTarget("    -1\n    58\n").has_value());  // refused at fuzz.uff:LINE:COL
  EXPECT_FALSE(runDirTarget("{}").has_value());               // "not a run record", naming run.json
}

// The judgement can fail: a scene error without a position, an internal or a third
// party's error, and a NaN or inf printed are breaches; a positioned scene error and a
// named numerical failure are not.
TEST(FuzzReplay, TheJudgementSeesEveryKindOfBreach) {
  const auto judge = [](auto error) { return judgeException(std::make_exception_ptr(error)); };
  EXPECT_FALSE(judge(SceneError("fuzz.yaml:3:7: links[0].length must be > 0 m (got 0)")).has_value());
  EXPECT_FALSE(judge(NumericalError("static equilibrium failed")).has_value());
  EXPECT_TRUE(judge(SceneError("fuzz.yaml: a HAM-SAS time run needs ground_motion")).has_value());
  EXPECT_TRUE(judge(InternalError("internal error: x failed")).has_value());
  EXPECT_TRUE(judge(std::invalid_argument("discretizeLink: E*I > 0")).has_value());
  EXPECT_FALSE(judgeOutput("mode 1  1.3365 Hz (infinite-looking is fine)", nlohmann::ordered_json{{"f", 1.3}}).has_value());
  EXPECT_TRUE(judgeOutput("span: inf", nlohmann::ordered_json::object()).has_value());
  EXPECT_TRUE(judgeOutput("f = -nan Hz", nlohmann::ordered_json::object()).has_value());
  EXPECT_TRUE(judgeOutput("", nlohmann::ordered_json{{"modes", {{{"f", std::nan("")}}}}}).has_value());
  // And the targets accept what is well formed or well refused.
  EXPECT_FALSE(readerTarget("links: 3\n").has_value());
  const auto ok = modesTarget(read(fs::path(MMVLAB_SOURCE_DIR) / "scenes/two-link-demo.yaml"));
  EXPECT_FALSE(ok.has_value()) << ok.value_or("");
}

}  // namespace
}  // namespace mmv::fuzz

// Progress on every verb (issue 38): a run that takes longer than the watchdog's
// interval says what it is doing on stderr, naming its stage. The interval is 15 s;
// MMVLAB_PROGRESS_INTERVAL shortens it here so each verb's ordinary run is "long".
#include <regex>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

class Progress : public Cli {
 protected:
  /// The progress lines a verb printed with a 5 ms interval; its exit code checked.
  std::string progressOf(const std::string& args) {
    const Result r = run(args, "MMVLAB_PROGRESS_INTERVAL=0.005 ");
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    std::string out;
    std::istringstream is(r.err);
    for (std::string line; std::getline(is, line);)
      if (line.rfind("mmvlab: still working (", 0) == 0 || std::regex_search(line, std::regex("^mmvlab: [a-z ,-]+: [0-9.e+-]+ of ")))
        out += line + "\n";
    return out;
  }
  std::string scene(const char* name) const { return (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / name).string(); }
};

// Every verb that computes: a line naming the verb first, then (where the run spends
// its time in one) the stage and its count.
TEST_F(Progress, EveryVerbNamesItsStageWhenItRunsLong) {
  const fs::path run_dir = dir_ / "run";
  ASSERT_EQ(run("simulate " + scene("mmv-slew.yaml") + " --out " + run_dir.string()).code, 0);
  const fs::path uff = dir_ / "frf" / "frf.uff";
  ASSERT_EQ(run("frf " + scene("mmv-table.yaml") + " --out " + (dir_ / "frf").string()).code, 0);
  struct Case {
    std::string args, expect;  ///< a regex the progress lines must hold
  };
  const std::vector<Case> cases{
      {"modes --segments 1024", "still working \\([0-9.]+ s\\): modes > eigen-solution: 12 modes of 4096 DOF"},
      {"converge", "still working \\([0-9.]+ s\\): converge"},
      {"compare --segments 32", "still working \\([0-9.]+ s\\): compare"},
      {"sweep-config --grid joint2:0:30:10", "still working \\([0-9.]+ s\\): sweep-config > configurations of the grid \\(configuration [0-9]+ of 4(, about [0-9]+ (s|min) left)?\\)"},
      // Its stages with a frequency count (the full model's responses, the reduced
      // model's comparison): the whole run is about 0.3 s, any of them may fall between
      // two 5 ms ticks on a loaded machine.
      {"frf --segments 64", "still working \\([0-9.]+ s\\): frf > .*\\(frequency [0-9]+ of [0-9]+(, about [0-9]+ (s|min) left)?\\)"},
      {"rom --segments 32 --out " + (dir_ / "rom").string(), "still working \\([0-9.]+ s\\): rom"},
      {"check --segments 32", "still working \\([0-9.]+ s\\): check > "},
      {"place-sensors --spacing 0.01", "still working \\([0-9.]+ s\\): place-sensors"},
      {"frf " + scene("hamsas.yaml"), "still working \\([0-9.]+ s\\): frf"},
      {"correlate " + scene("mmv-table.yaml") + " --measured " + uff.string() + " --modes 12", "still working \\([0-9.]+ s\\): correlate"},
      {"render --mode 1 --size 320x240 --out " + (dir_ / "m.mp4").string(), "still working \\([0-9.]+ s\\): render > drawing the mode's cycle \\(frame [0-9]+ of 48(, about [0-9]+ (s|min) left)?\\)"},
      {"render --history " + run_dir.string() + " --size 64x48 --out " + (dir_ / "h.mp4").string(),
       "still working \\([0-9.]+ s\\): render > drawing the run's frames \\(frame [0-9]+ of [0-9]+(, about [0-9]+ (s|min) left)?\\)"},
      {"report --segments 32 --out " + (dir_ / "report").string(), "still working \\([0-9.]+ s\\): report > report: "},
      {"simulate " + scene("mmv-slew.yaml"), "mmvlab: time run, seconds simulated: [0-9.e+-]+ of "},
      {"sweep " + (fs::path(MMVLAB_SOURCE_DIR) / "sweeps/link3-sizing.yaml").string() + " --out " + (dir_ / "sweep").string(),
       "mmvlab: sweep, points done: [0-9]+ of 117"},
  };
  for (const auto& c : cases) {
    const std::string p = progressOf(c.args);
    EXPECT_TRUE(std::regex_search(p, std::regex(c.expect))) << c.args << "\nprinted:\n" << p.substr(0, 2000);
  }
}

// Without the variable the interval is 15 s: a short run prints no progress at all.
TEST_F(Progress, AShortRunPrintsNone) {
  const Result r = run("modes --segments 32");
  ASSERT_EQ(r.code, 0);
  EXPECT_EQ(r.err.find("still working"), std::string::npos) << r.err;
}

// MMVLAB_STAGE_TIMES (docs/benchmarks.md): each stage's wall time as it closes, nested
// stages indented under the command's, which closes last; none without the variable.
TEST_F(Progress, StageTimesNameEveryStageAndTheCommandLast) {
  const Result r = run("modes --segments 8", "MMVLAB_STAGE_TIMES=1 ");
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<std::string> lines;
  std::istringstream is(r.err);
  for (std::string line; std::getline(is, line);)
    if (line.rfind("mmvlab: stage ", 0) == 0) lines.push_back(line);
  ASSERT_GE(lines.size(), 3u) << r.err;
  EXPECT_TRUE(std::regex_search(r.err, std::regex("mmvlab: stage   +[0-9.]+ ms  eigen-solution: [0-9]+ modes of 32 DOF\\n")))
      << r.err;
  EXPECT_TRUE(std::regex_match(lines.back(), std::regex("mmvlab: stage [0-9.]+ ms  modes"))) << lines.back();
  EXPECT_EQ(run("modes --segments 8").err.find("mmvlab: stage"), std::string::npos);
}

}  // namespace
}  // namespace mmv::cli_testing

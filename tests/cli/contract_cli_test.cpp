// The command-line contract at its edges (issue 16): a misspelt command is named with a
// suggestion, bytes from the user are escaped before they reach the terminal, scene
// paths that are not regular files are refused before anything reads them (so nothing
// hangs), numeric options say what they need without CLI11's 309-digit bound, and a
// full standard output is a failure.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/cli.hpp"

namespace {

using namespace mmv::cli_testing;

TEST_F(Cli, MisspeltCommandIsNamedWithASuggestion) {
  const Result r = run("mode");
  EXPECT_EQ(r.code, 64);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("unknown command 'mode' (did you mean 'modes'?)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("place-sensors"), std::string::npos) << r.err;  // the list of commands
}

TEST_F(Cli, ControlBytesAndInvalidUtf8AreEscaped) {
  const Result r = run("\"$(printf 'mo\\001de\\377')\"");
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("mo\\x01de\\xFF"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\x01'), std::string::npos);
  EXPECT_EQ(r.err.find('\xff'), std::string::npos);
}

TEST_F(Cli, MissingSceneSaysWhy) {
  const Result r = run("modes " + (dir_ / "nope.yaml").string());
  EXPECT_EQ(r.code, 66);
  EXPECT_NE(r.err.find("No such file or directory"), std::string::npos) << r.err;
}

// /dev/zero never ends and a FIFO without a writer blocks for ever: both must be refused
// at once (the timeout turns a regression into a failure instead of a hung suite).
TEST_F(Cli, DevicesAndFifosAreNotScenes) {
  const fs::path fifo = dir_ / "scene.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string path : {std::string("/dev/zero"), fifo.string()}) {
    const fs::path err = dir_ / "err";
    const std::string cmd = "timeout 60 " + std::string(MMVLAB_BINARY) + " modes " + path + " >/dev/null 2>" + err.string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 66) << path;  // 124: the timeout fired
    EXPECT_NE(slurp(err).find("is not a regular file"), std::string::npos) << slurp(err);
  }
}

TEST_F(Cli, OversizedSceneIsRefusedUnread) {
  const fs::path big = dir_ / "big.yaml";
  std::ofstream(big) << "name: big\n";
  fs::resize_file(big, (16L << 20) + 1);  // sparse: costs no disk
  const Result r = run("modes " + big.string());
  EXPECT_EQ(r.code, 66);
  EXPECT_NE(r.err.find("a scene file is at most 16777216 bytes"), std::string::npos) << r.err;
}

TEST_F(Cli, EmptyScenePathIsAUsageError) {
  const Result r = run("modes \"\"");
  EXPECT_EQ(r.code, 64);
  EXPECT_EQ(r.out, "");
  EXPECT_NE(r.err.find("empty scene path"), std::string::npos) << r.err;
}

TEST_F(Cli, NumericOptionsStateWhatTheyNeed) {
  for (const std::string args : {"simulate --duration -1", "simulate --sample-rate nan", "modes --modes -1",
                                 "trade --duration inf"}) {
    const Result r = run(args);
    EXPECT_EQ(r.code, 64) << args;
    EXPECT_NE(r.err.find("must be a finite number"), std::string::npos) << args << ": " << r.err;
    EXPECT_LT(r.err.size(), 200u) << args << ": " << r.err;  // no 309-digit bound
  }
}

TEST_F(Cli, FullStandardOutputIsAFailure) {
  // --version and --help too (they exited 0 with their text lost, issue 68).
  for (const char* args : {"modes --segments 2", "--version", "--help", "modes --help"}) {
    const std::string cmd = std::string(MMVLAB_BINARY) + " " + args + " >/dev/full 2>" + (dir_ / "err").string();
    const int status = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(status)) << args;
    EXPECT_EQ(WEXITSTATUS(status), 74) << args;
    EXPECT_NE(slurp(dir_ / "err").find("cannot write to standard output"), std::string::npos) << args;
  }
}

}  // namespace

namespace {

// The SUNDIALS plugin carries its own SUNDIALS 6 with every symbol hidden, so it cannot
// interpose on (or be interposed by) the older copy inside Debian's libSimTKmath, and
// needs no RTLD_DEEPBIND (which sanitizers refuse): its dynamic symbol table defines the
// factory and no SUNDIALS name, and it needs no SUNDIALS shared library. (Running
// Simbody's CPodes and the plugin's integrators in one process is
// Simulation.FlexibleSlewIntegratorsAgree.)
TEST_F(Cli, SundialsPluginExportsOnlyItsFactory) {
  const fs::path plugin = fs::path(MMVLAB_BINARY).parent_path() / "libmmvlab_sundials.so";
  ASSERT_TRUE(fs::exists(plugin));
  const fs::path syms = dir_ / "syms", libs = dir_ / "libs";
  ASSERT_EQ(std::system(("nm -D --defined-only " + plugin.string() + " >" + syms.string()).c_str()), 0);
  ASSERT_EQ(std::system(("ldd " + plugin.string() + " >" + libs.string()).c_str()), 0);
  const std::string defined = slurp(syms);
  EXPECT_NE(defined.find(" T mmv_create_sundials_stepper"), std::string::npos) << defined;
  for (const char* name : {"CVode", "ARKStep", "IDA", "N_V", "SUN"})
    EXPECT_EQ(defined.find(std::string(" ") + name), std::string::npos) << name << " exported:\n" << defined;
  EXPECT_EQ(slurp(libs).find("libsundials"), std::string::npos) << slurp(libs);
}

// matio and its HDF5's network stack (curl, gnutls, Kerberos, ssh) live in the .mat
// plugin, loaded on the first .mat file (Cli.CommandsWithoutImagesDoNotLoadTheImageStack
// sees which commands load it); the plugin exports one symbol and needs nothing of
// mmvlab's.
TEST_F(Cli, TheMatPluginExportsOnlyItsTable) {
  const fs::path syms = dir_ / "syms";
  const fs::path plugin = fs::path(MMVLAB_BINARY).parent_path() / "libmmvlab_mat.so";
  ASSERT_TRUE(fs::exists(plugin));
  ASSERT_EQ(std::system(("nm -D --defined-only " + plugin.string() + " >" + syms.string()).c_str()), 0);
  const std::string defined = slurp(syms);
  EXPECT_NE(defined.find(" T mmvlab_mat_api"), std::string::npos) << defined;
  EXPECT_EQ(std::count(defined.begin(), defined.end(), '\n'), 1) << defined;
}

}  // namespace

namespace {

/// A CSV without its wall-time-dependent columns (trade's cpu_s and pareto), for
/// comparing two runs' files.
std::string withoutTimedColumns(const std::string& csv) {
  std::istringstream in(csv);
  std::vector<bool> keep;
  std::string line, out;
  for (bool header = true; std::getline(in, line); header = false) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    if (header)
      for (const auto& c : cells) keep.push_back(c != "cpu_s" && c != "pareto");
    for (std::size_t i = 0; i < cells.size(); ++i)
      if (i >= keep.size() || keep[i]) out += cells[i] + ",";
    out += "\n";
  }
  return out;
}

/// Entries of `dir` whose names start with the staging prefix.
/// Staging directories in `dir`; `pid` > 0: only that process's (named by its pid).
int stagingLeft(const fs::path& dir, pid_t pid = 0) {
  const std::string prefix = ".mmvlab-staging-" + (pid > 0 ? std::to_string(pid) + "-" : std::string());
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().rfind(prefix, 0) == 0;
  return n;
}

// SIGKILL (which no handler sees) and SIGINT at seeded random moments of a simulate and
// a trade run with --out: the directory is either absent or holds every file of a
// complete run, the data files equal to an undisturbed run's; a SIGINT leaves
// no staging directory, and the next run sweeps away those a SIGKILL left.
// render writes a video through `.mmvlab-PID-NAME` beside --out. Before, a SIGINT,
// SIGTERM, SIGHUP or SIGKILL left that file and no later run removed it. Now a SIGINT
// removes it, and a temporary whose process is gone (what a SIGKILL leaves) is removed
// by the next render writing there.
TEST_F(Cli, RenderLeavesNoTemporaryBehind) {
  const auto temporaries = [&] {
    std::vector<std::string> t;
    for (const auto& e : fs::directory_iterator(dir_))
      if (e.path().filename().string().rfind(".mmvlab-", 0) == 0) t.push_back(e.path().filename().string());
    return t;
  };
  const pid_t pid = spawn(split(std::string(MMVLAB_BINARY) + " render --mode 1 --size 640x360 --out " + (dir_ / "m.mp4").string()));
  ASSERT_GT(pid, 0);
  const auto start = std::chrono::steady_clock::now();
  while (temporaries().empty() && std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(temporaries().size(), 1u) << "the video's temporary never appeared";
  ::kill(pid, SIGINT);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(temporaries().empty()) << temporaries()[0];
  EXPECT_FALSE(fs::exists(dir_ / "m.mp4"));
  // A SIGKILLed run's temporary: a process that has exited, its pid on a file.
  const pid_t gone = ::fork();
  if (gone == 0) ::_exit(0);
  ::waitpid(gone, &status, 0);
  const std::string stale = ".mmvlab-" + std::to_string(gone) + "-k.mp4";
  write(stale, "half a video");
  write(".mmvlab-staging-notmine", "x");  // not a temporary of this kind: kept
  const Result r = run("render --out " + (dir_ / "a.png").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / stale));
  EXPECT_TRUE(fs::exists(dir_ / ".mmvlab-staging-notmine"));
}

// render --force replaced a link or a FIFO of the output's name (exit 0; issue 68): it
// refuses them as every other verb does, before drawing, with or without --force, and
// the link's target and the FIFO stay as they were.
TEST_F(Cli, RenderNeverReplacesALinkOrAFifo) {
  write("target.png", "the link's target");
  fs::create_symlink(dir_ / "target.png", dir_ / "link.png");
  ASSERT_EQ(::mkfifo((dir_ / "fifo.png").c_str(), 0600), 0);
  fs::create_directory(dir_ / "dir.png");
  for (const char* name : {"link.png", "fifo.png", "dir.png"})
    for (const char* force : {"", " --force"}) {
      const Result r = run("render --size 64x64 --out " + (dir_ / name).string() + force);
      EXPECT_EQ(r.code, 73) << name << force << r.err;
      EXPECT_NE(r.err.find("not a regular file"), std::string::npos) << name << force << r.err;
    }
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.png"));
  EXPECT_EQ(slurp(dir_ / "target.png"), "the link's target");
  EXPECT_TRUE(fs::is_fifo(dir_ / "fifo.png"));
  EXPECT_TRUE(fs::is_directory(dir_ / "dir.png"));
  // A regular file: refused without --force, replaced with it.
  write("mine.png", "x");
  EXPECT_EQ(run("render --size 64x64 --out " + (dir_ / "mine.png").string()).code, 73);
  EXPECT_EQ(slurp(dir_ / "mine.png"), "x");
  EXPECT_EQ(run("render --size 64x64 --out " + (dir_ / "mine.png").string() + " --force").code, 0);
  EXPECT_TRUE(isPng(dir_ / "mine.png"));
}

TEST_F(Cli, KilledRunsLeaveNoPartialFile) {
  struct Case {
    std::string args;      // after the binary; OUT is appended
    std::string data;      // a data file to compare with the undisturbed run's (timed columns aside)
  };
  const std::vector<Case> cases{
      {"simulate " MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml --segments 2 --duration 2 --sample-rate 2000 --out", "history.csv"},
      {"trade " MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml --integrators rk_merson,cvode_bdf --accuracies 1e-3,1e-5 "
       "--segment-ladder 2,4 --duration 0.5 --all --out",  // --all: no run cut by wall time, the same rows every run
       "trade.csv"}};
  std::mt19937 rng(20261123);
  for (const Case& c : cases) {
    const fs::path ref = dir_ / "ref";
    fs::remove_all(ref);
    const auto t0 = std::chrono::steady_clock::now();
    ASSERT_EQ(run(c.args + " " + ref.string()).code, 0) << c.args;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(ref)) names.insert(e.path().filename().string());
    const std::string data = withoutTimedColumns(slurp(ref / c.data));
    int complete = 0, cut_short = 0;
    for (int k = 0; k < 6; ++k) {
      const int sig = k % 3 == 2 ? SIGINT : SIGKILL;
      const fs::path out = dir_ / (c.data + "-run" + std::to_string(k));
      const pid_t pid = spawn(split(std::string(MMVLAB_BINARY) + " " + c.args + " " + out.string()));
      ASSERT_GT(pid, 0);
      std::this_thread::sleep_for(std::chrono::duration<double>(std::uniform_real_distribution<double>(0, 1.2 * seconds)(rng)));
      ::kill(pid, sig);
      int status = 0;
      ::waitpid(pid, &status, 0);
      (fs::exists(out) ? complete : cut_short) += 1;
      if (fs::exists(out)) {
        std::set<std::string> got;
        for (const auto& e : fs::directory_iterator(out))
          if (e.path().filename().string().rfind(".mmvlab-staging-", 0) != 0) got.insert(e.path().filename().string());
        EXPECT_EQ(got, names) << c.args << ", signal " << sig << " after the run had made " << out;
        EXPECT_EQ(withoutTimedColumns(slurp(out / c.data)), data) << c.args << ", signal " << sig;
      }
      // Its own: a SIGINT that lands before the run has swept (a slow start under the
      // sanitizers) leaves an earlier SIGKILL's staging directory, which the last run
      // below must sweep.
      if (sig == SIGINT) EXPECT_EQ(stagingLeft(dir_, pid), 0) << "SIGINT left a staging directory";
    }
    // The seeded moments must really interrupt runs (else only complete runs are seen).
    EXPECT_GT(cut_short, 0) << c.args << " (" << complete << " runs had finished)";
  }
  // The next run in the same place removes what the SIGKILLs left.
  ASSERT_EQ(run("modes --segments 2 --json >/dev/null; " + std::string(MMVLAB_BINARY) + " compare --segments 2 --out " +
                (dir_ / "after").string()).code, 0);
  EXPECT_EQ(stagingLeft(dir_), 0);
}

TEST_F(Cli, EmptyOutIsAUsageError) {
  const Result c = run("compare --segments 2 --out \"\"");
  EXPECT_EQ(c.code, 64);
  EXPECT_NE(c.err.find("empty path"), std::string::npos) << c.err;
}

// Nothing is created for a run that fails: --out under missing parents stays absent.
TEST_F(Cli, FailedRunCreatesNoDirectory) {
  const fs::path out = dir_ / "a" / "b" / "c";
  const Result r = run("compare " + (dir_ / "missing.yaml").string() + " --out " + out.string());
  EXPECT_EQ(r.code, 66);
  EXPECT_FALSE(fs::exists(dir_ / "a"));
}

}  // namespace

namespace {

// A length meant in mm (the 2,660 kg article with a kilometre of sag) is named
// as a likely unit mistake by `modes` too, not only by `check`; the shipped scene is not.
TEST_F(Cli, ModesNamesALikelyUnitMistake) {
  const Result bad = run("modes --segments 2 --set links.link1.length=2440");
  EXPECT_EQ(bad.code, 0) << bad.err;
  EXPECT_NE(bad.out.find("warning: likely a unit mistake: --set links.link1.length=2440: links[0] (link1).length 2440 m"),
            std::string::npos) << bad.out;
  EXPECT_NE(bad.err.find("links[0] (link1).length 2440 m is longer than a lab can hold"), std::string::npos) << bad.err;  // at load
  EXPECT_NE(bad.out.find("given in mm"), std::string::npos);
  const Result json = run("modes --segments 2 --json --set links.link1.length=2440");
  EXPECT_NE(json.out.find("\"warnings\""), std::string::npos);
  const Result good = run("modes --segments 2");
  EXPECT_EQ(good.out.find("likely a unit mistake"), std::string::npos) << good.out;
}

}  // namespace

namespace {

// Segments per link are bounded where dense matrices still fit (1024: 4096 DOF, 1.3 GB;
// 4096 would need about 20 GB): above it the option is a usage error and the scene key
// a scene error with its position, before any model is built.
TEST_F(Cli, SegmentCountIsBounded) {
  const Result opt = run("modes --segments 1025");
  EXPECT_EQ(opt.code, 64);
  EXPECT_NE(opt.err.find("1025"), std::string::npos) << opt.err;
  const Result key = run("modes " MMVLAB_SOURCE_DIR "/scenes/two-link-demo.yaml --set links.upper.segments=4096");
  EXPECT_EQ(key.code, 65) << key.err;
  EXPECT_NE(key.err.find("segments must be an integer from 1 to 1024"), std::string::npos) << key.err;
}

// The other counts docs/reliability.md bounds on the command line: one past each limit
// is a usage error, the limit itself is accepted by the parser.
TEST_F(Cli, DocumentedCountLimitsAreEnforced) {
  EXPECT_EQ(run("frf --segments 2 --points 100001").code, 64);
  EXPECT_EQ(run("place-sensors --segments 2 --count 100001").code, 64);
  EXPECT_EQ(run("converge --max-segments 1025").code, 64);
  const Result at_limit = run("place-sensors --segments 2 --count 100000");
  EXPECT_NE(at_limit.err.find("--count"), std::string::npos) << at_limit.err;  // refused by the analysis, not the parser
}

}  // namespace

namespace {

// Misspelt scene keys and point names get the closest valid ones (every one at the
// smallest edit distance), before the full list.
TEST_F(Cli, MisspeltKeysAndPointsGetSuggestions) {
  const fs::path scene = write("typo.yaml", "name: x\nlinks: []\ngravty: 1\n");
  const Result key = run("modes " + scene.string());
  EXPECT_EQ(key.code, 65);
  EXPECT_NE(key.err.find(":3:1: unknown key 'gravty' (did you mean 'gravity'?) (allowed:"), std::string::npos) << key.err;
  const Result point = run("modes --points link3.tip");
  EXPECT_EQ(point.code, 64);
  EXPECT_NE(point.err.find("(did you mean 'link1.tip', 'link2.tip', 'link3a.tip' or 'link3b.tip'?)"), std::string::npos)
      << point.err;
  const Result far = run("modes --points zzzzzz");
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;  // nothing close: no guess
}

}  // namespace

// The file-system fault harness (issue 38; docs/reliability.md, "Faults"): every verb
// with --out runs under a shim (tests/faults/write_fault.cpp, LD_PRELOAD) that fails
// its n-th write to a regular file with ENOSPC or EIO, or makes it short, for n over
// the run's writes (stdout to a file counts as one). The transaction rule:
//   - a failure exits 73 (cannot create the output) or 74 (stdout), never 0, never 70,
//     never a signal, with a message;
//   - --out holds exactly what it held before (a user's own file, and the outputs of an
//     earlier run that --force would have replaced), and no staging or temporary is
//     left beside it or in it;
//   - a short write is finished (the writers loop) and the run succeeds whole.
#include <signal.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include "support/cli.hpp"
#include "support/sanitizers.hpp"

namespace mmv::cli_testing {
namespace {

using Tree = std::map<std::string, std::string>;  ///< relative path -> contents ("<dir>" for a directory)

Tree snapshot(const fs::path& root) {
  Tree t;
  if (!fs::exists(root)) return t;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string rel = fs::relative(e.path(), root).string();
    // Staging and temporaries (.mmvlab-*): not outputs; leftovers() looks for them. The
    // record of what mmvlab wrote (.mmvlab-outputs) is part of the folder.
    if (rel.rfind(".mmvlab-", 0) == 0 && rel != ".mmvlab-outputs") continue;
    t[rel] = e.is_directory() ? "<dir>" : slurp(e.path());
  }
  return t;
}

std::vector<std::string> leftovers(const fs::path& dir) {
  std::vector<std::string> out;
  for (const fs::path& where : {dir.parent_path(), dir})
    if (fs::is_directory(where))
      for (const auto& e : fs::directory_iterator(where)) {
        const std::string n = e.path().filename().string();
        if (n.rfind(".mmvlab", 0) == 0 && n != ".mmvlab-outputs") out.push_back(e.path().string());
        if (n.rfind(".journal.csv", 0) == 0 || n.rfind(".sweep.csv", 0) == 0) out.push_back(e.path().string());
      }
  return out;
}

class Faults : public Cli {
 protected:
  struct Verb {
    std::string name;
    std::string args;  ///< with {out} for the output directory (or file)
    std::string file;  ///< --out is one file of this name (render), not a directory
    /// The user's earlier output is made by these args instead of `args` (when the verb's
    /// output is the same every run: the new one must differ to be seen).
    std::string earlier;
    /// The writes counted on a second run into the first one's folder (a sweep resumes
    /// its journal there and writes only its outputs).
    bool count_rerun = false;
  };

  Result runWith(const std::string& args, const std::string& fault) {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr", report = dir_ / "count";
    // Under the sanitizers: the shim comes before libasan (verify_asan_link_order=0), and no
    // leak check at exit: LeakSanitizer's own tracer crashed (signal 11, "LeakSanitizer has
    // encountered a fatal error") at the exit of a render whose encoder had just met ENOSPC
    // under the shim. This harness checks the transaction rule; leaks are checked by the
    // rest of the sanitized suite, which runs the same verbs without the shim.
    const std::string env = "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0:detect_leaks=0\" LD_PRELOAD=" +
                            std::string(MMVLAB_WRITE_FAULT) + " MMVLAB_FAULT=" + fault + " MMVLAB_FAULT_REPORT=" + report.string() + " ";
    const int status = std::system((env + MMVLAB_BINARY + " " + args + " >" + out.string() + " 2>" + err.string()).c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  static std::string with(std::string args, const fs::path& out) {
    const auto at = args.find("{out}");
    return args.replace(at, 5, out.string());
  }

  /// The verb's writes counted on a clean run into a fresh directory; then the
  /// directory prepared as a user has it (a file of theirs and a finished earlier run);
  /// then each chosen write failed in turn, the rule checked after each.
  void exercise(const Verb& v, int samples) {
    const fs::path home = dir_ / v.name;
    fs::create_directories(home);
    const fs::path out = !v.file.empty() ? home / v.file : home / "out";
    const std::string args = with(v.args, out) + " --force";
    // A clean run: the count, and the earlier outputs that --force replaces.
    Result counted = runWith(args, "count");
    ASSERT_EQ(counted.code, 0) << v.name << ": " << counted.err;
    if (v.count_rerun) counted = runWith(args, "count");
    ASSERT_EQ(counted.code, 0) << v.name << ": " << counted.err;
    const long writes = std::atol(slurp(dir_ / "count").c_str());
    ASSERT_GT(writes, 0) << v.name << ": no write to a regular file was seen";
    if (!v.earlier.empty()) {
      const Result e = runWith(with(v.earlier, out) + " --force", "count");
      ASSERT_EQ(e.code, 0) << v.name << ": " << e.err;
    }
    if (v.file.empty()) {
      std::ofstream(out / "notes-of-mine.txt") << "the user's own file\n";
    }
    Tree before = snapshot(!v.file.empty() ? home : out);
    // Under the sanitizers, the first, middle and last writes only, one kind of failure
    // at each (EIO at the first, a full disk at the middle, a short write at the last):
    // every kind still meets an error path and every stage's place is failed once; the
    // writes between them and the other pairings run the same code, which the plain suite
    // fails at every sample (a sanitized run of a verb costs 3-10x its plain run).
    const bool sanitized = mmv::testing::kUnderSanitizers;
    if (sanitized) samples = std::min(samples, 2);
    std::set<long> points{1, writes};
    for (int i = 1; i < samples; ++i) points.insert(1 + (writes - 1) * i / samples);
    const long middle = *std::next(points.begin(), static_cast<long>(points.size()) / 2);
    int failures = 0;
    for (long n : points)
      for (const char* kind : {"enospc", "eio", "short"}) {
        const std::string k(kind);
        if (k != "enospc" && n != 1 && n != writes && n != middle)
          continue;  // EIO and short writes at the first, middle and last write
        if (sanitized && !((k == "eio" && n == 1) || (k == "enospc" && n == middle) || (k == "short" && n == writes)))
          continue;
        const std::string fault = k + ":" + std::to_string(n);
        const Result r = runWith(args, fault);
        const std::string where = v.name + " with " + fault + " of " + std::to_string(writes) + " writes";
        EXPECT_EQ(leftovers(out), std::vector<std::string>{}) << where;
        if (k == "short") {
          EXPECT_EQ(r.code, 0) << where << ": a short write must be finished\n" << r.err;
          if (!v.earlier.empty()) EXPECT_EQ(runWith(with(v.earlier, out) + " --force", "count").code, 0) << where;  // different again
          before = snapshot(!v.file.empty() ? home : out);  // a new, whole run: what the next fault must leave
          continue;
        }
        EXPECT_TRUE(r.code == 73 || r.code == 74) << where << ": exit " << r.code << "\n" << r.err;
        EXPECT_EQ(r.err.find("internal error"), std::string::npos) << where << "\n" << r.err;
        EXPECT_NE(r.err.find("mmvlab: "), std::string::npos) << where << ": no message";
        const Tree after = snapshot(!v.file.empty() ? home : out);
        EXPECT_TRUE(after == before) << where << ": --out changed (" << before.size() << " entries before, " << after.size()
                                     << " after)\n" << r.err;
        if (after != before) {
          for (const auto& [k, c] : before)
            if (!after.count(k) || after.at(k) != c) ADD_FAILURE() << where << ": " << k << (after.count(k) ? " changed" : " gone");
          for (const auto& [k, c] : after)
            if (!before.count(k)) ADD_FAILURE() << where << ": " << k << " appeared";
        }
        ++failures;
      }
    EXPECT_GT(failures, 0);
  }

  std::string scene(const char* name) const { return (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / name).string(); }
};

// The harness can see a failure: the shim counts writes to regular files only, fails
// the one it is told to (and every one after: a full disk stays full), and lets a
// short write through as short (dd, writing 3-byte blocks, is the program under test).
TEST_F(Faults, TheShimFailsTheWriteItIsToldTo) {
  const fs::path f = dir_ / "f.bin", report = dir_ / "count";
  auto dd = [&](const std::string& fault, const std::string& of, int blocks) {
    const std::string cmd = "LD_PRELOAD=" + std::string(MMVLAB_WRITE_FAULT) + " MMVLAB_FAULT=" + fault + " MMVLAB_FAULT_REPORT=" +
                            report.string() + " dd if=/dev/zero of=" + of + " bs=3 count=" + std::to_string(blocks) +
                            " iflag=fullblock status=none 2>/dev/null";
    const int status = std::system(cmd.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(dd("count", f.string(), 4), 0);
  EXPECT_EQ(slurp(report), "4\n");
  EXPECT_EQ(dd("count", "/dev/null", 4), 0);
  EXPECT_EQ(slurp(report), "0\n");  // not a regular file
  EXPECT_NE(dd("enospc:3", f.string(), 4), 0);
  EXPECT_EQ(fs::file_size(f), 6u);  // two blocks, then the disk is full
  EXPECT_NE(dd("eio:1", f.string(), 4), 0);
  EXPECT_EQ(fs::file_size(f), 0u);
  EXPECT_EQ(dd("short:2", f.string(), 4), 0);  // dd finishes a short write itself
  EXPECT_EQ(fs::file_size(f), 12u);
}

TEST_F(Faults, ModesConvergeCompareAndCheckLeaveOutAsItWas) {
  exercise({"modes", "modes --segments 4 --out {out}"}, 8);
  exercise({"converge", "converge --out {out}"}, 6);
  exercise({"compare", "compare --segments 4 --out {out}"}, 8);
  exercise({"check", "check --segments 4 --out {out}"}, 6);
}

TEST_F(Faults, FrfAndRomLeaveOutAsItWas) {
  exercise({"frf", "frf --segments 4 --out {out}"}, 8);
  exercise({"rom", "rom --segments 4 --out {out}"}, 8);
}

TEST_F(Faults, SimulateSweepConfigAndPlaceSensorsLeaveOutAsItWas) {
  exercise({"simulate", "simulate " + scene("mmv-slew.yaml") + " --segments 2 --duration 0.2 --out {out}"}, 8);
  exercise({"sweep-config", "sweep-config --segments 4 --grid joint2:0:20:10 --out {out}"}, 6);
  exercise({"place-sensors", "place-sensors --segments 4 --out {out}"}, 6);
}

// The sweep under the same rule (issue 68): over a finished sweep of the same spec (its
// resume writes sweep.csv, sweep.json, the figures and the record) every failed write
// leaves the folder as it was; into a new folder, a full disk or an I/O error at the
// journal's first write leaves no folder, no lock, no temporary behind.
TEST_F(Faults, SweepLeavesOutAsItWas) {
  const fs::path spec = dir_ / "spec.yaml";
  std::ofstream(spec) << "scene: " << scene("mmv.yaml") << "\nsegments: 4\nparameters:\n"
                      << "  - {key: links.link2.length, values: [1.4, 1.6]}\noutputs: [frequencies, mass, check]\nmodes: 2\n";
  Verb sweep{"sweep", "sweep " + spec.string() + " --out {out}"};
  sweep.count_rerun = true;
  exercise(sweep, 6);
  for (const char* fault : {"enospc:1", "eio:1", "enospc:2"}) {
    const fs::path fresh = dir_ / "fresh" / "out";
    const Result r = runWith("sweep " + spec.string() + " --out " + fresh.string(), fault);
    EXPECT_EQ(r.code, 73) << fault << ": " << r.err;
    EXPECT_FALSE(fs::exists(fresh)) << fault << ": the run's new folder is left";
    EXPECT_EQ(leftovers(fresh), std::vector<std::string>{}) << fault;
  }
}

TEST_F(Faults, CorrelateUpdateAndRenderLeaveOutAsItWas) {
  const Result f = run("frf " + scene("mmv-table.yaml") + " --segments 4 --out " + (dir_ / "measured").string());
  ASSERT_EQ(f.code, 0) << f.err;
  exercise({"correlate", "correlate " + scene("mmv-table.yaml") + " --segments 4 --measured " + (dir_ / "measured" / "frf.uff").string() +
                             " --modes 6 --out {out}"},
           6);
  exercise({"update", "update " + scene("mmv-table.yaml") + " --segments 4 --measured " + (dir_ / "measured" / "frf.uff").string() +
                          " --modes 6 --params joints.joint2.torquer.mass:4:5 --out {out}"},
           6);
  exercise({"render", "render --segments 4 --size 160x120 --out {out}", "out.png"}, 4);
  exercise({"render-video", "render --segments 4 --mode 1 --size 160x120 --out {out}", "out.mp4"}, 6);
}

// The review page: its figures are drawn into the staging directory's scratch space and
// inlined, so a failure at any of them (or at report.html, report.json) leaves --out as it
// was and no figure file behind.
TEST_F(Faults, ReportLeavesOutAsItWas) {
  exercise({"report", "report --segments 2 --out {out}", "", "report --segments 2 --modes 4 --out {out}"}, 6);
}

// A run for ParaView: the frames (an OutputDir of their own, out_frames/) and the .pvd
// that lists them, written last: a failure at any write, the .pvd's included, leaves both
// as they were (the frames put back).
TEST_F(Faults, RenderOfARunToParaViewLeavesOutAsItWas) {
  const fs::path run_dir = dir_ / "run";
  const Result r = run("simulate " + scene("mmv-slew.yaml") + " --segments 2 --duration 0.2 --out " + run_dir.string());
  ASSERT_EQ(r.code, 0) << r.err;
  // The earlier output at 20 frames/s: its frames differ from the new run's (at 30).
  const std::string render = "render --history " + run_dir.string() + " --fps ";
  exercise({"render-pvd", render + "30 --out {out}", "out.pvd", render + "20 --out {out}"}, 6);
}

// The signal harness: each verb killed at moments spread over a clean run's duration,
// by SIGINT, SIGTERM, SIGHUP (caught: staging removed, then the default action) and
// SIGKILL (not caught: the next run on the same --out removes what it left). After
// each, --out holds either what it held before or a whole new output (a kill after the
// commit), never a mix, and after the next run no staging is left anywhere.
//
// Under the sanitizers the runs here check no leaks (detect_leaks=0, as the write-fault
// harness above): a clean render once exited 1 here on CI with no finding of ours to
// show (LeakSanitizer's stop-the-world tracer died, "Tracer caught signal 11",
// google/sanitizers#1353; the cause was later found in GCC 12's __tls_get_addr hook and
// tests/sanitized.sh now sets intercept_tls_get_addr=0, docs/reliability.md). Leaks are
// checked by the rest of the sanitized suite, which runs the same verbs; what a run here
// printed is shown with any unexpected exit code.
class Signals : public Faults {
 protected:
  void SetUp() override {
    Faults::SetUp();
    const char* asan = std::getenv("ASAN_OPTIONS");
    ::setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + (asan && *asan ? ":" : "") + "detect_leaks=0").c_str(), 1);
  }
  void killAtMoments(const Verb& v) {
    const fs::path home = dir_ / v.name;
    fs::create_directories(home);
    const fs::path out = !v.file.empty() ? home / v.file : home / "out";
    const std::string args = with(v.args, out) + " --force";
    const auto t0 = std::chrono::steady_clock::now();
    const Result first = run(args);
    ASSERT_EQ(first.code, 0) << v.name << ": " << first.err;
    const double clean = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (v.file.empty()) std::ofstream(out / "notes-of-mine.txt") << "the user's own file\n";
    const Tree whole = snapshot(!v.file.empty() ? home : out);
    const int sigs[] = {SIGINT, SIGTERM, SIGHUP, SIGKILL};
    // What a SIGKILL left is removed by the next run that gets as far as its --out; one
    // killed before that (early in its run) leaves it there, so it is not that run's.
    std::vector<std::string> killed_staging;
    const auto ownLeftovers = [&] {
      std::vector<std::string> own;
      for (const auto& l : leftovers(out))
        if (std::none_of(killed_staging.begin(), killed_staging.end(),
                         [&](const std::string& k) { return l.find(k) != std::string::npos; }))
          own.push_back(l);
      return own;
    };
    for (int k = 0; k < 8; ++k) {
      const Tree before = snapshot(!v.file.empty() ? home : out);
      const int sig = sigs[k % 4];
      const pid_t pid = spawn(split(std::string(MMVLAB_BINARY) + " " + args));
      std::this_thread::sleep_for(std::chrono::duration<double>(clean * (0.05 + 0.12 * k)));
      ::kill(pid, sig);
      int status = 0;
      ::waitpid(pid, &status, 0);
      const std::string where = v.name + " killed by signal " + std::to_string(sig) + " at " + std::to_string(0.05 + 0.12 * k) + " of its run";
      EXPECT_FALSE(WIFSIGNALED(status) && WTERMSIG(status) != sig) << where << ": died of signal " << WTERMSIG(status);
      if (WIFEXITED(status)) EXPECT_EQ(WEXITSTATUS(status), 0) << where << ": finished before the signal, yet failed";
      const Tree after = snapshot(!v.file.empty() ? home : out);
      bool same_names = after.size() == whole.size();
      for (const auto& [name, c] : whole) same_names = same_names && after.count(name);
      EXPECT_TRUE(after == before || same_names) << where << ": --out is neither as it was nor a whole output (" << after.size()
                                                 << " entries, " << whole.size() << " in a whole one)";
      for (const auto& [name, c] : after)
        if (c != "<dir>") EXPECT_FALSE(c.empty() && !whole.at(name).empty()) << where << ": " << name << " is empty";
      if (sig != SIGKILL) EXPECT_EQ(ownLeftovers(), std::vector<std::string>{}) << where;
      else
        for (const char* prefix : {"/.mmvlab-staging-", "/.mmvlab-"}) killed_staging.push_back(prefix + std::to_string(pid) + "-");
    }
    const Result last = run(args);
    ASSERT_EQ(last.code, 0) << v.name << ": the run after the kills: " << last.err;
    EXPECT_EQ(leftovers(out), std::vector<std::string>{}) << v.name << ": a SIGKILL's staging outlived the next run";
  }
};

TEST_F(Signals, EveryVerbKilledAnywhereLeavesOutWholeOrAsItWas) {
  killAtMoments({"modes", "modes --segments 16 --out {out}"});
  killAtMoments({"frf", "frf --segments 8 --out {out}"});
  killAtMoments({"rom", "rom --segments 8 --out {out}"});
  killAtMoments({"check", "check --segments 8 --out {out}"});
  killAtMoments({"simulate", "simulate " + scene("mmv-slew.yaml") + " --segments 2 --duration 0.5 --out {out}"});
  killAtMoments({"sweep-config", "sweep-config --segments 4 --grid joint2:0:40:10 --out {out}"});
  killAtMoments({"place-sensors", "place-sensors --segments 8 --out {out}"});
  killAtMoments({"compare", "compare --segments 8 --out {out}"});
  killAtMoments({"report", "report --segments 4 --out {out}"});
  killAtMoments({"render-video", "render --segments 4 --mode 1 --size 320x240 --out {out}", "out.mp4"});
}

}  // namespace
}  // namespace mmv::cli_testing

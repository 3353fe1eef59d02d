// The sweep runner (sim/plan/design_sweep.hpp): serial, parallel and sharded runs write
// the same file; a torn or corrupt journal is cut back and resumed without a duplicate.
#include "sim/plan/design_sweep.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "sim/core/errors.hpp"
#include "support/cli.hpp"

namespace mmv {
namespace {

namespace fs = std::filesystem;

using cli_testing::slurp;

class SweepRunner : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = cli_testing::freshTestDir("mmvlab_runner_"); }
  void TearDown() override { fs::remove_all(dir_); }

  DesignSweepRun run(const std::string& sub, int jobs, Shard shard = {}) {
    DesignSweepRun r;
    r.dir = (dir_ / sub).string();
    r.fingerprint = "abc";
    r.header = {"point", "square", "label"};
    r.total_points = 50;
    r.shard = shard;
    r.jobs = jobs;
    r.evaluate = [this](long i) {
      ++evaluated_;
      return std::vector<std::string>{std::to_string(i * i), "p" + std::to_string(i % 7)};
    };
    return r;
  }
  fs::path dir_;
  std::atomic<long> evaluated_{0};
};

TEST_F(SweepRunner, SerialParallelAndShardsMergedWriteTheSameFile) {
  const std::string serial = runDesignSweep(run("serial", 1), false).table;
  EXPECT_EQ(serial.substr(0, 19), "point,square,label\n");
  EXPECT_EQ(std::count(serial.begin(), serial.end(), '\n'), 51);
  EXPECT_EQ(runDesignSweep(run("parallel", 4), false).table, serial);
  for (int n : {1, 2, 3}) {
    std::vector<std::string> dirs;
    for (int i = 1; i <= n; ++i) dirs.push_back(run("s" + std::to_string(n) + "_" + std::to_string(i), 2, {i, n}).dir);
    for (int i = 1; i <= n; ++i) runDesignSweep(run("s" + std::to_string(n) + "_" + std::to_string(i), 2, {i, n}), false);
    EXPECT_EQ(mergeSweepTables(dirs), serial) << n << " shards";
  }
}

TEST_F(SweepRunner, ATornAndACorruptJournalAreCutBackAndResumed) {
  const std::string whole = runDesignSweep(run("whole", 2), false).table;
  // A run killed mid-way: 10 good rows, then a row with a missing field, then a torn line.
  const DesignSweepRun r = run("killed", 2);
  fs::create_directories(r.dir);
  const std::string journal = slurp(dir_ / "whole" / "journal.csv");
  std::size_t cut = 0;
  for (int lines = 0; lines < 12; ++lines) cut = journal.find('\n', cut) + 1;
  std::ofstream(fs::path(r.dir) / "journal.csv", std::ios::binary) << journal.substr(0, cut) << "40,1600\n41,1681,p";
  evaluated_ = 0;
  const DesignSweepRunResult res = runDesignSweep(r, false);
  EXPECT_EQ(res.reused, 10);
  EXPECT_EQ(res.computed, 40);
  EXPECT_EQ(evaluated_, 40);
  EXPECT_EQ(res.table, whole);
  // Resumed again: nothing left to compute, the same table.
  evaluated_ = 0;
  const DesignSweepRunResult again = runDesignSweep(r, false);
  EXPECT_EQ(again.computed, 0);
  EXPECT_EQ(evaluated_, 0);
  EXPECT_EQ(again.table, whole);
}

// A row holding nan or inf (never written by a sweep: a hand edit) is computed again,
// not carried into sweep.csv (where it reached the figures and crashed the heat map).
TEST_F(SweepRunner, AJournalRowHoldingANonFiniteNumberIsComputedAgain) {
  const std::string whole = runDesignSweep(run("whole", 2), false).table;
  for (const char* bad : {"nan", "inf", "-Infinity"}) {
    const DesignSweepRun r = run(std::string("bad_") + (bad[0] == '-' ? "minf" : bad), 2);
    fs::create_directories(r.dir);
    std::string journal = slurp(dir_ / "whole" / "journal.csv");
    const std::size_t at = journal.find("\n3,9,");
    ASSERT_NE(at, std::string::npos);
    journal.replace(at + 3, 1, bad);
    std::ofstream(fs::path(r.dir) / "journal.csv", std::ios::binary) << journal;
    const DesignSweepRunResult res = runDesignSweep(r, false);
    // The rows before point 3's kept, it and those after it again. Two jobs journal the
    // points as they finish (0, 1, 3, 2 as often as 0, 1, 2, 3): count the rows before
    // it, less the journal's two header lines.
    const long before = std::count(journal.begin(), journal.begin() + static_cast<long>(at) + 1, '\n') - 2;
    EXPECT_EQ(res.reused, before) << bad;
    EXPECT_EQ(res.table, whole) << bad;
  }
}

// The journal is read like any input file: a device or a FIFO in its place is refused
// (a FIFO blocked the run forever, /dev/zero grew to gigabytes).
TEST_F(SweepRunner, AJournalThatIsNotARegularFileIsRefused) {
  const DesignSweepRun r = run("fifo", 2);
  fs::create_directories(r.dir);
  ASSERT_EQ(mkfifo((fs::path(r.dir) / "journal.csv").c_str(), 0600), 0);
  try {
    runDesignSweep(r, false);
    FAIL() << "a FIFO journal was accepted";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
  }
  const DesignSweepRun z = run("zero", 2);
  fs::create_directories(z.dir);
  fs::create_symlink("/dev/zero", fs::path(z.dir) / "journal.csv");
  EXPECT_THROW(runDesignSweep(z, false), OutputError);
}

// Two sweeps on one --out at once computed every point twice into one journal; the
// second is now refused while the first holds the directory's lock.
TEST_F(SweepRunner, ASecondSweepOnTheSameDirectoryIsRefusedWhileTheFirstRuns) {
  const DesignSweepRun r = run("busy", 2);
  fs::create_directories(r.dir);
  const int fd = ::open((fs::path(r.dir) / ".mmvlab-sweep.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);  // as a running sweep holds it
  try {
    runDesignSweep(r, false);
    FAIL() << "ran beside another sweep";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("is in use by another sweep"), std::string::npos) << e.what();
  }
  EXPECT_EQ(evaluated_, 0);
  ::close(fd);  // the first one ends: the directory is free again
  EXPECT_EQ(runDesignSweep(r, false).computed, 50);
}

TEST_F(SweepRunner, AnotherSweepsDirectoryIsRefusedUnlessRestarted) {
  runDesignSweep(run("a", 2), false);
  DesignSweepRun other = run("a", 2);
  other.fingerprint = "def";
  EXPECT_THROW(runDesignSweep(other, false), OutputError);
  EXPECT_EQ(runDesignSweep(other, true).computed, 50);
  DesignSweepRun shard = run("a", 2, {2, 3});
  shard.fingerprint = "def";
  EXPECT_THROW(runDesignSweep(shard, false), OutputError);  // the directory holds shard 1/1
}

TEST_F(SweepRunner, MergeRefusesMissingAndOverlappingPoints) {
  runDesignSweep(run("s1", 2, {1, 3}), false);
  runDesignSweep(run("s2", 2, {2, 3}), false);
  try {
    mergeSweepTables({(dir_ / "s1").string(), (dir_ / "s2").string()});
    FAIL() << "merged with a shard missing";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("16 of 50 points are missing (2, 5, 8"), std::string::npos) << e.what();
  }
  EXPECT_THROW(mergeSweepTables({(dir_ / "s1").string(), (dir_ / "s1").string()}), OutputError);
}

// A run that fails before it has computed a point leaves the folder as it was: no
// journal, lock or temporary of its own, no folder it made; an older sweep's journal
// that --force was replacing is put back. One that computed points keeps them.
TEST_F(SweepRunner, AFailedRunLeavesTheFolderAsItWasOrItsPointsResumable) {
  DesignSweepRun r = run("fresh", 1);
  r.evaluate = [](long) -> std::vector<std::string> { throw NumericalError("the first point fails"); };
  EXPECT_THROW(runDesignSweep(r, false), NumericalError);
  EXPECT_FALSE(fs::exists(r.dir));  // the folder it made, removed
  // --force over another sweep's journal, failing at once: the old journal is back.
  const DesignSweepRun old = run("old", 1);
  runDesignSweep(old, false);
  const std::string before = slurp(fs::path(old.dir) / "journal.csv");
  DesignSweepRun other = run("old", 1);
  other.fingerprint = "another";
  other.evaluate = r.evaluate;
  EXPECT_THROW(runDesignSweep(other, /*restart=*/true), NumericalError);
  EXPECT_EQ(slurp(fs::path(old.dir) / "journal.csv"), before);
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(old.dir)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"journal.csv"});  // no lock, no aside, no temporary
  // Failing after three points: they stay in a journal the same run resumes.
  DesignSweepRun later = run("later", 1);
  later.evaluate = [](long i) -> std::vector<std::string> {
    if (i == 3) throw NumericalError("point 3 fails");
    return {std::to_string(i * i), "p" + std::to_string(i % 7)};
  };
  EXPECT_THROW(runDesignSweep(later, false), NumericalError);
  EXPECT_EQ(readSweepJournal(later.dir).rows.size(), 3u);
  EXPECT_FALSE(fs::exists(fs::path(later.dir) / ".mmvlab-sweep.lock"));
  EXPECT_EQ(runDesignSweep(run("later", 1), false).reused, 3);
}

// Only the sweep's own journal is ever replaced: a user's file, folder (empty or not) or
// link named journal.csv is refused, --force or not, and left as it was.
TEST_F(SweepRunner, AJournalThatIsNotASweepsIsNeverReplaced) {
  const DesignSweepRun r = run("user", 1);
  fs::create_directories(r.dir);
  const fs::path j = fs::path(r.dir) / "journal.csv";
  for (const bool restart : {false, true}) {
    std::ofstream(j, std::ios::binary) << "my,own\n1,2\n";
    EXPECT_THROW(runDesignSweep(r, restart), OutputError) << restart;
    EXPECT_EQ(slurp(j), "my,own\n1,2\n") << restart;
    fs::remove(j);
    fs::create_directory(j);
    EXPECT_THROW(runDesignSweep(r, restart), OutputError) << restart;
    EXPECT_TRUE(fs::is_directory(j));
    std::ofstream(j / "keep.txt") << "x";
    EXPECT_THROW(runDesignSweep(r, restart), OutputError) << restart;  // was exit 70 (filesystem_error)
    EXPECT_TRUE(fs::exists(j / "keep.txt"));
    fs::remove_all(j);
    std::ofstream(dir_ / "target.csv") << "t";
    fs::create_symlink(dir_ / "target.csv", j);
    EXPECT_THROW(runDesignSweep(r, restart), OutputError) << restart;
    EXPECT_TRUE(fs::is_symlink(j));
    EXPECT_EQ(slurp(dir_ / "target.csv"), "t");
    fs::remove(j);
  }
  EXPECT_EQ(evaluated_, 0);
}

}  // namespace
}  // namespace mmv

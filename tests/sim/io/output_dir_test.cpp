// OutputDir's promises (sim/io/output_dir.hpp): nothing in DIR before commit, no
// directory created for a run that never commits, and with --force old files replaced
// only when every new one is in place.
#include "sim/io/output_dir.hpp"

#include <gtest/gtest.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "sim/core/files.hpp"
#include "support/cli.hpp"

namespace mmv {
namespace {

namespace fs = std::filesystem;
using cli_testing::slurp;

class OutputDirTest : public ::testing::Test {
 protected:
  void SetUp() override { root_ = cli_testing::freshTestDir("mmvlab_outdir_"); }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(OutputDirTest, NothingAppearsBeforeCommitAndNoDirectoryWithoutIt) {
  const fs::path target = root_ / "a" / "b";
  {
    OutputDir out(target.string(), false);
    std::ofstream(out.stage("x.csv")) << "1\n";
    EXPECT_FALSE(fs::exists(root_ / "a"));  // staged in the nearest existing ancestor
  }  // destroyed without commit: a failed run
  EXPECT_FALSE(fs::exists(root_ / "a"));
  EXPECT_TRUE(fs::is_empty(root_));  // no staging directory left either
}

// A report's figures: written beside the staged files, read back, never moved into DIR
// nor left behind (commit removes them, so the staging can go after a signal too).
TEST_F(OutputDirTest, ScratchFilesAreNeitherCommittedNorLeft) {
  const fs::path target = root_ / "page";
  std::string scratch;
  {
    OutputDir out(target.string(), false);
    scratch = out.scratch("figure.png");
    writeFileChecked(scratch, "png bytes");
    EXPECT_EQ(slurp(scratch), "png bytes");
    out.write("report.html", "<html>");
    out.commit();
    EXPECT_FALSE(fs::exists(scratch));
    EXPECT_EQ(out.targets(), std::vector<std::string>{(target / "report.html").string()});
  }
  EXPECT_FALSE(fs::exists(target / "figure.png"));
  EXPECT_FALSE(fs::exists(target / ".scratch-figure.png"));
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(target)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"report.html"});
}

TEST_F(OutputDirTest, StagesInsideAnExistingDirectory) {
  OutputDir out(root_.string(), false);
  std::ofstream(out.stage("x.csv")) << "1\n";
  int staging = 0;
  for (const auto& e : fs::directory_iterator(root_)) staging += e.is_directory();
  EXPECT_EQ(staging, 1);  // DIR/.mmvlab-staging-PID-NAME: a mount point or a read-only parent works
  out.commit();
  EXPECT_EQ(slurp(root_ / "x.csv"), "1\n");
}

// The transaction ends with the OutputDir: a failure after the commit (standard output
// that cannot be written) puts DIR back as it was, the replaced files and all. Before,
// `rom --out D > /dev/full` exited 74 with D written.
TEST_F(OutputDirTest, AFailureAfterTheCommitPutsEverythingBack) {
  std::ofstream(root_ / "a.csv") << "old a\n";
  const fs::path fresh = root_ / "new_dir";
  EXPECT_THROW(
      {
        OutputDir out(root_.string(), true);
        out.write("a.csv", "new a\n");
        out.write("b.csv", "new b\n");
        out.commit();
        EXPECT_EQ(slurp(root_ / "a.csv"), "new a\n");
        throw StdoutError("standard output is full");
      },
      StdoutError);
  EXPECT_EQ(slurp(root_ / "a.csv"), "old a\n");
  EXPECT_FALSE(fs::exists(root_ / "b.csv"));
  EXPECT_THROW(
      {
        OutputDir out(fresh.string(), false);
        out.write("a.csv", "x");
        out.commit();
        throw StdoutError("standard output is full");
      },
      StdoutError);
  EXPECT_FALSE(fs::exists(fresh));  // the directory the run made is gone too
  int left = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(root_)) ++left;
  EXPECT_EQ(left, 1);  // a.csv: no staging directory left
}

// --force replaces only the files mmvlab writes: a directory (with the user's files in
// it) that has an output's name is refused, untouched. Before, `simulate --out R2
// --force` deleted R2/tips.png/ and everything under it.
TEST_F(OutputDirTest, ForceNeverReplacesADirectory) {
  fs::create_directories(root_ / "tips.png");
  std::ofstream(root_ / "tips.png" / "mine.txt") << "keep\n";
  OutputDir out(root_.string(), true);
  out.write("tips.png", "png");
  EXPECT_THROW(out.commit(), OutputError);
  EXPECT_EQ(slurp(root_ / "tips.png" / "mine.txt"), "keep\n");
}

// Every write is checked: a full disk is an OutputError naming the file, never a short
// file with success (/dev/full fails every write with ENOSPC).
TEST_F(OutputDirTest, AFullDiskIsAnError) {
  try {
    writeFileChecked("/dev/full", std::string(100000, 'x'));
    ADD_FAILURE() << "no error";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full: cannot write: No space left on device"), std::string::npos) << e.what();
  }
  OutputDir out(root_.string(), false);
  const std::string staged = out.stage("empty.png");  // a library that failed quietly: an empty file
  std::ofstream(staged).flush();
  EXPECT_THROW(out.commit(), OutputError);
  EXPECT_FALSE(fs::exists(root_ / "empty.png"));
}

// The second new file cannot be placed (its staged copy is gone): the commit fails and
// the first old file is back as it was, the second old one untouched.
TEST_F(OutputDirTest, ForcedCommitThatFailsRestoresTheOldFiles) {
  std::ofstream(root_ / "a.csv") << "old a\n";
  std::ofstream(root_ / "b.csv") << "old b\n";
  OutputDir out(root_.string(), true);
  std::ofstream(out.stage("a.csv")) << "new a\n";
  const std::string b = out.stage("b.csv");
  std::ofstream(b) << "new b\n";
  fs::remove(b);
  EXPECT_THROW(out.commit(), OutputError);
  EXPECT_EQ(slurp(root_ / "a.csv"), "old a\n");
  EXPECT_EQ(slurp(root_ / "b.csv"), "old b\n");
}

TEST_F(OutputDirTest, CommitWithoutForceRefusesToReplace) {
  std::ofstream(root_ / "a.csv") << "old a\n";
  OutputDir out(root_.string(), false);
  std::ofstream(out.stage("a.csv")) << "new a\n";
  EXPECT_THROW(out.commit(), OutputError);
  EXPECT_EQ(slurp(root_ / "a.csv"), "old a\n");
}

TEST_F(OutputDirTest, AFileOrAnEmptyNameIsRefused) {
  std::ofstream(root_ / "file") << "x";
  EXPECT_THROW(OutputDir((root_ / "file").string(), false), OutputError);
  EXPECT_THROW(OutputDir((root_ / "file" / "sub").string(), false), OutputError);
  EXPECT_THROW(OutputDir("", false), OutputError);
}

// The kernel may hand a SIGTERM to any thread; here it goes to a worker while the main
// thread keeps rewriting its staged files. The cleanup must not run beside that writing
// (a file recreated after its unlink kept the staging directory alive, as the signal
// harness once saw): the worker passes the signal to the staging thread, which stops,
// cleans and dies of it. Run in a child process, which the signal ends.
TEST_F(OutputDirTest, ASignalToAnotherThreadStillRemovesTheStaging) {
  for (int round = 0; round < 5; ++round) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      OutputDir out((root_ / "out").string(), false);
      std::vector<std::string> staged;
      for (int i = 0; i < 50; ++i) staged.push_back(out.stage("f" + std::to_string(i) + ".csv"));
      std::atomic<bool> writing{false};
      std::thread worker([&writing] {
        while (!writing.load()) std::this_thread::yield();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ::pthread_kill(::pthread_self(), SIGTERM);
        std::this_thread::sleep_for(std::chrono::seconds(10));
      });
      for (long n = 0;; ++n) {
        std::ofstream(staged[n % staged.size()]) << n << '\n';
        writing.store(true);
      }
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << "round " << round << ": status " << status;
    EXPECT_EQ(WTERMSIG(status), SIGTERM) << "round " << round;
    EXPECT_TRUE(fs::is_empty(root_)) << "round " << round << ": staging left behind";
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
}

}  // namespace
}  // namespace mmv

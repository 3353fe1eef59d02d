// OutputDir's promises (sim/io/output_dir.hpp): nothing in DIR before commit, no
// directory created for a run that never commits, and with --force old files replaced
// only when every new one is in place.
#include "sim/io/output_dir.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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

TEST_F(OutputDirTest, StagesInsideAnExistingDirectory) {
  OutputDir out(root_.string(), false);
  std::ofstream(out.stage("x.csv")) << "1\n";
  int staging = 0;
  for (const auto& e : fs::directory_iterator(root_)) staging += e.is_directory();
  EXPECT_EQ(staging, 1);  // DIR/.mmvlab-staging-PID-NAME: a mount point or a read-only parent works
  EXPECT_EQ(out.commit().size(), 1u);
  EXPECT_EQ(slurp(root_ / "x.csv"), "1\n");
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

}  // namespace
}  // namespace mmv

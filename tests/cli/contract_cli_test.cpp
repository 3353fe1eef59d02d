// The command-line contract at its edges (issue 16): a misspelt command is named with a
// suggestion, bytes from the user are escaped before they reach the terminal, scene
// paths that are not regular files are refused before anything reads them (so nothing
// hangs), numeric options say what they need without CLI11's 309-digit bound, and a
// full standard output is a failure.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <string>

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
  const std::string cmd = std::string(MMVLAB_BINARY) + " modes --segments 2 >/dev/full 2>" + (dir_ / "err").string();
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 74);
  EXPECT_NE(slurp(dir_ / "err").find("cannot write to standard output"), std::string::npos);
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

}  // namespace

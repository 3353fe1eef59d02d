#pragma once
// Test support: the mmvlab executable run as a user runs it (exit code, stdout,
// stderr), in a private directory per test.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mmv::cli_testing {

namespace fs = std::filesystem;

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

/// A fresh, empty directory under the system's temporary one, private to this process
/// and the running test: `prefix`PID_TESTNAME.
/// A free pendulum released exactly horizontal: its tangent stiffness is singular, so
/// every analysis fails building its equilibrium (exit 1, named). `segments`: "rigid" or N.
inline std::string singularPendulumScene(const std::string& segments) {
  return "name: horizontal pendulum\n"
         "materials: {m: {density: 1000, youngs_modulus: 1e9}}\n"
         "sections: {s: {shape: explicit, area: 1e-4, second_moment: 1e-10}}\n"
         "base: {direction_deg: -90}\n"
         "joints: [{name: j1, parent: base, angle_deg: 90, hold: free}]\n"
         "links: [{name: l1, joint: j1, material: m, section: s, length: 1.0, segments: " + segments + "}]\n";
}

/// A directory of its own for the running test. A parameterised test's name has a '/'
/// ("KeepsTheContract/3"): it is flattened so that the directory removed at the end is
/// the one made here, not a child of a directory left behind in /tmp.
inline fs::path freshTestDir(const std::string& prefix) {
  std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  for (char& c : name)
    if (c == '/') c = '_';
  const fs::path d = fs::temp_directory_path() / (prefix + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

inline bool isPng(const fs::path& p) {
  const std::string head = slurp(p).substr(0, 8);
  return head == std::string("\x89PNG\r\n\x1a\n", 8);
}

/// Starts `args` (split on spaces) as a child with stdout and stderr discarded.
inline pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::FILE* null = std::freopen("/dev/null", "w", stdout);
    null = std::freopen("/dev/null", "w", stderr);
    (void)null;
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

inline std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream is(s);
  for (std::string w; is >> w;) out.push_back(w);
  return out;
}

struct Result {
  int code = -1;
  std::string out, err;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestDir("mmvlab_cli_"); }
  void TearDown() override { fs::remove_all(dir_); }

  /// `env`: variables set for this run only, "NAME=VALUE " (shell words, with their space).
  Result run(const std::string& args, const std::string& env = "") {
    const fs::path out = dir_ / "stdout", err = dir_ / "stderr";
    const std::string cmd = env + std::string(MMVLAB_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    Result r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
  }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p;
  }

  fs::path dir_;
};

}  // namespace mmv::cli_testing

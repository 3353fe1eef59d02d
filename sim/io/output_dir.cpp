#include "sim/io/output_dir.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

namespace mmv {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStagingPrefix = ".mmvlab-staging-";

/// What a signal handler removes: the files staged so far and their directories, as
/// plain C strings in static storage (unlink and rmdir are async-signal-safe; nothing
/// here allocates).
struct SignalCleanup {
  static constexpr int kMaxPaths = 256;
  std::array<std::array<char, 4096>, kMaxPaths> paths{};
  std::array<char, kMaxPaths> is_dir{};
  volatile sig_atomic_t count = 0;
};
SignalCleanup g_cleanup;

void removeStagedAndReraise(int sig) {
  for (int i = g_cleanup.count - 1; i >= 0; --i)
    (g_cleanup.is_dir[i] ? ::rmdir : ::unlink)(g_cleanup.paths[i].data());
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void remember(const fs::path& p, bool dir) {
  const std::string s = p.string();
  const int i = g_cleanup.count;
  if (i >= SignalCleanup::kMaxPaths || s.size() >= g_cleanup.paths[i].size()) return;  // left for the next run's sweep
  std::memcpy(g_cleanup.paths[i].data(), s.c_str(), s.size() + 1);
  g_cleanup.is_dir[i] = dir;
  g_cleanup.count = i + 1;
  static const bool installed = [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, removeStagedAndReraise);
    return true;
  }();
  (void)installed;
}

void forgetAll() { g_cleanup.count = 0; }

/// Staging directories left by runs that were killed (SIGKILL cannot be handled): their
/// process is gone, so they are removed.
void removeStaleStaging(const fs::path& base) {
  std::error_code ec;
  for (fs::directory_iterator it(base, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kStagingPrefix, 0) != 0) continue;
    const long pid = std::strtol(name.c_str() + std::strlen(kStagingPrefix), nullptr, 10);
    if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) {
      std::error_code ignore;
      fs::remove_all(it->path(), ignore);
    }
  }
}

}  // namespace

OutputDir::OutputDir(const std::string& dir, bool force) : force_(force) {
  if (dir.empty()) throw OutputError("--out: empty directory name");
  std::error_code ec;
  target_ = dir;  // as the user wrote it, for messages; relative paths stay valid (no chdir)
  const fs::path absolute = fs::absolute(target_, ec);
  if (ec) throw OutputError(dir + ": " + ec.message());
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec))
    throw OutputError(dir + ": exists and is not a directory");
  // Staged inside DIR when it exists (a mount point, or a writable DIR under a read-only
  // parent, works), else in its nearest existing ancestor, where DIR will be created: the
  // final renames never cross a file system, and a failed run creates no directory.
  fs::path base = absolute;
  while (!fs::exists(base, ec) && base.has_parent_path() && base != base.parent_path()) base = base.parent_path();
  if (!fs::is_directory(base, ec)) throw OutputError(dir + ": " + base.string() + " is not a directory");
  removeStaleStaging(base);
  staging_ = base / (kStagingPrefix + std::to_string(::getpid()) + "-" + absolute.filename().string());
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec)) throw OutputError(dir + ": cannot write in " + base.string() + ": " + ec.message());
  remember(staging_, true);
}

OutputDir::~OutputDir() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  forgetAll();
}

std::string OutputDir::stage(const std::string& name) {
  names_.push_back(name);
  remember(staging_ / name, false);
  return (staging_ / name).string();
}

std::vector<std::string> OutputDir::commit() {
  std::error_code ec;
  if (!force_) {
    for (const auto& n : names_)
      if (fs::exists(target_ / n, ec))
        throw OutputError((target_ / n).string() + " exists: nothing was written (use --force to replace)");
  }
  fs::create_directories(target_, ec);
  if (ec) throw OutputError(target_.string() + ": cannot create directory: " + ec.message());
  // --force: the old files are moved aside first and put back if any new one cannot be
  // placed, so a failure never leaves the user with fewer files than before.
  std::vector<std::string> aside, placed;
  const auto undo = [&]() {
    std::error_code ignore;
    for (const auto& n : placed) fs::remove(target_ / n, ignore);
    for (const auto& n : aside) fs::rename(staging_ / (".old-" + n), target_ / n, ignore);
  };
  for (const auto& n : names_) {
    if (!fs::exists(target_ / n, ec)) continue;
    fs::rename(target_ / n, staging_ / (".old-" + n), ec);
    if (ec) {
      undo();
      throw OutputError((target_ / n).string() + ": cannot replace: " + ec.message());
    }
    aside.push_back(n);
  }
  std::vector<std::string> out;
  for (const auto& n : names_) {
    fs::rename(staging_ / n, target_ / n, ec);
    if (ec) {
      undo();
      throw OutputError((target_ / n).string() + ": cannot write: " + ec.message());
    }
    placed.push_back(n);
    out.push_back((target_ / n).string());
  }
  committed_ = true;
  return out;
}

}  // namespace mmv

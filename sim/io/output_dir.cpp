#include "sim/io/output_dir.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "sim/core/files.hpp"
#include "sim/core/text.hpp"

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

// A signal that arrives while files are being moved into DIR (or the transaction ends)
// waits until they are consistent again: the handler, on whichever thread it runs, only
// records it then, and the section's end acts on it. Both sides take it with exchange(),
// so it is acted on exactly once.
std::atomic<int> g_in_critical{0}, g_pending_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "async-signal-safe only when lock free");

/// In a handler the raised signal is blocked until the handler returns; it then ends the
/// process with the signal's default action.
void removeStagedAndReraise(int sig) {
  for (int i = g_cleanup.count - 1; i >= 0; --i)
    (g_cleanup.is_dir[i] ? ::rmdir : ::unlink)(g_cleanup.paths[i].data());
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

/// The thread that stages files (the main one). A signal the kernel hands to another
/// thread (a worker, the progress watchdog) is passed on to it, so the cleanup never runs
/// beside a thread that is still creating files in the staging directory.
pthread_t g_owner;

void onSignal(int sig) {
  if (!pthread_equal(pthread_self(), g_owner)) {
    pthread_kill(g_owner, sig);
    return;
  }
  g_pending_signal.store(sig);
  if (g_in_critical.load() != 0) return;
  if (const int s = g_pending_signal.exchange(0)) removeStagedAndReraise(s);
}

void installHandlers() {
  static const bool installed = [] {
    g_owner = pthread_self();
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::signal(sig, onSignal);
    return true;
  }();
  (void)installed;
}

/// While one lives, SIGINT, SIGTERM and SIGHUP are held back (see above).
struct SignalsHeld {
  SignalsHeld() { g_in_critical.store(1); }
  ~SignalsHeld() {
    g_in_critical.store(0);
    if (const int s = g_pending_signal.exchange(0)) removeStagedAndReraise(s);
  }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;
};

void remember(const fs::path& p, bool dir) {
  installHandlers();
  const std::string s = p.string();
  const int i = g_cleanup.count;
  if (i >= SignalCleanup::kMaxPaths || s.size() >= g_cleanup.paths[i].size()) return;  // left for the next run's sweep
  std::memcpy(g_cleanup.paths[i].data(), s.c_str(), s.size() + 1);
  g_cleanup.is_dir[i] = dir;
  g_cleanup.count = i + 1;
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

/// The process id in a temporary's name `.mmvlab-PID-NAME` (0: not such a name).
long temporaryOwner(const std::string& name) {
  const std::string prefix = ".mmvlab-";
  if (name.rfind(prefix, 0) != 0) return 0;
  char* end = nullptr;
  const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
  return end && *end == '-' && end != name.c_str() + prefix.size() ? pid : 0;
}

/// A file's size and FNV-1a 64-bit hash, as the outputs record lists it; nullopt-like
/// (false) when it cannot be read.
bool fingerprintOf(const fs::path& p, std::uintmax_t& size, std::uint64_t& hash) {
  std::ifstream in(p, std::ios::binary);
  if (!in) return false;
  hash = 1469598103934665603ull;
  size = 0;
  char buf[65536];
  while (in) {
    in.read(buf, sizeof buf);
    const std::streamsize n = in.gcount();
    for (std::streamsize i = 0; i < n; ++i) hash = (hash ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
    size += static_cast<std::uintmax_t>(n);
  }
  return in.eof();
}

struct RecordEntry {
  std::uintmax_t size = 0;
  std::uint64_t hash = 0;
};
constexpr const char* kRecordMagic = "# mmvlab outputs v1";

/// DIR's outputs record (empty when there is none or it is not one). A name may have two
/// entries: the file it replaced and the new one, both listed while the files are moved
/// in (a SIGKILL between two renames leaves each file, old or new, listed as it is).
using Record = std::multimap<std::string, RecordEntry>;
Record readRecord(const fs::path& dir) {
  Record entries;
  std::string text, why;
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(dir / kOutputsRecord, ec))) return entries;
  if (!readInputFile((dir / kOutputsRecord).string(), 16L << 20, text, why)) return entries;
  std::istringstream is(text);
  std::string line;
  if (!std::getline(is, line) || line != kRecordMagic) return entries;
  while (std::getline(is, line)) {
    std::istringstream ls(line);
    RecordEntry e;
    std::string hex, name;
    if (!(ls >> e.size >> hex) || !std::getline(ls, name) || name.size() < 2 || name[0] != ' ') continue;
    e.hash = std::strtoull(hex.c_str(), nullptr, 16);
    entries.emplace(name.substr(1), e);
  }
  return entries;
}

/// Empty when `dir/name` is absent or is, as it is now, a file the record lists; else why not.
std::string notOwn(const fs::path& dir, const std::string& name, const Record& record) {
  std::error_code ec;
  const fs::path t = dir / name;
  const fs::file_status st = fs::symlink_status(t, ec);
  if (!fs::exists(st)) return {};
  if (!fs::is_regular_file(st)) return t.string() + " exists and is not a regular file (a folder, a link or a device)";
  std::uintmax_t size = 0;
  std::uint64_t hash = 0;
  const bool readable = record.count(name) && fingerprintOf(t, size, hash);
  const auto [from, to] = record.equal_range(name);
  for (auto it = from; readable && it != to; ++it)
    if (size == it->second.size && hash == it->second.hash) return {};
  return t.string() + " exists and was not written by mmvlab here (or was changed since)";
}

/// Throws OutputError ("...: nothing was <done>") unless the record is a regular file if
/// it exists and each of `names` is absent or listed in it as it is now.
void requireOwn(const fs::path& dir, const std::vector<std::string>& names, const Record& record, const char* done) {
  std::error_code ec;
  const fs::file_status rs = fs::symlink_status(dir / kOutputsRecord, ec);
  if (fs::exists(rs) && !fs::is_regular_file(rs))
    throw OutputError((dir / kOutputsRecord).string() + " exists and is not a regular file: nothing was " + done);
  for (const auto& n : names) {
    const std::string why = notOwn(dir, n, record);
    if (!why.empty())
      throw OutputError(why + ": nothing was " + done + " (mmvlab replaces only files it wrote; move it or use another --out)");
  }
}

std::string recordLine(const std::string& name, std::uintmax_t size, std::uint64_t hash) {
  return std::to_string(size) + " " + strf("%016llx", static_cast<unsigned long long>(hash)) + " " + name + "\n";
}

}  // namespace

void checkOwnOutputs(const std::string& dir, const std::vector<std::string>& names) {
  std::error_code ec;
  const fs::file_status ds = fs::status(dir, ec);
  if (!fs::exists(ds)) return;
  if (!fs::is_directory(ds)) throw OutputError(dir + ": exists and is not a directory: nothing was computed");
  requireOwn(dir, names, readRecord(dir), "computed");
}

void removeOnSignal(const std::string& path) { remember(path, false); }
void forgetRemovalsOnSignal() { forgetAll(); }

void removeStaleTemporaries(const std::string& dir) {
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const long pid = temporaryOwner(it->path().filename().string());
    std::error_code type;
    if (pid > 0 && it->is_regular_file(type) && ::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) {
      std::error_code ignore;
      fs::remove(it->path(), ignore);
    }
  }
}

OutputDir::OutputDir(const std::string& dir, bool force) : force_(force), exceptions_at_start_(std::uncaught_exceptions()) {
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
  remember(staging_, true);  // before it exists: a signal in between finds nothing to remove
  if (!fs::create_directory(staging_, ec)) throw OutputError(dir + ": cannot write in " + base.string() + ": " + ec.message());
}

OutputDir::~OutputDir() {
  const SignalsHeld held;  // the undo (or the drop of the replaced files) runs whole
  if (committed_ && std::uncaught_exceptions() > exceptions_at_start_) undoCommit();
  else if (silent_) {
  } else if (!report_as_.empty() && !placed_.empty())
    std::cerr << "mmvlab: wrote " << placed_.size() << ' ' << report_as_ << " in " << target_.string() << '\n';
  else
    for (const auto& n : placed_)
      if (n != kOutputsRecord) std::cerr << "mmvlab: wrote " << (target_ / n).string() << '\n';
  std::error_code ec;
  fs::remove_all(staging_, ec);
  forgetAll();  // before `held` acts on a signal that came meanwhile: nothing left to remove
}

std::string OutputDir::stage(const std::string& name) {
  names_.push_back(name);
  remember(staging_ / name, false);
  return (staging_ / name).string();
}

std::string OutputDir::scratch(const std::string& name) {
  const fs::path p = staging_ / (".scratch-" + name);
  scratch_.push_back(p.string());
  remember(p, false);
  return p.string();
}

void OutputDir::write(const std::string& name, std::string_view bytes) { writeFileChecked(stage(name), bytes); }

void OutputDir::undoCommit() {
  std::error_code ignore;
  // An old file goes back over its new one in one rename; a new file with no old one goes.
  for (const auto& n : placed_)
    if (std::find(aside_.begin(), aside_.end(), n) == aside_.end()) fs::remove(target_ / n, ignore);
  for (const auto& n : aside_) fs::rename(staging_ / (".old-" + n), target_ / n, ignore);
  placed_.clear();
  aside_.clear();
  if (created_target_) fs::remove(target_, ignore);  // only if empty: a directory this run made
}

void OutputDir::stageRecord() {
  // Only files the record lists as they are now are replaced. The record written lists
  // each file it listed that is there as listed (a file about to be replaced too, so
  // that a SIGKILL between two renames leaves every file listed as it then is), and every
  // file placed now; it is placed first.
  const Record record = readRecord(target_);
  requireOwn(target_, names_, record, "written");
  std::error_code ec;
  std::string text = std::string(kRecordMagic) + "\n";
  for (const auto& [name, e] : record) {
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    const fs::path t = target_ / name;
    if (fs::is_regular_file(fs::symlink_status(t, ec)) && fingerprintOf(t, size, hash) && size == e.size && hash == e.hash)
      text += recordLine(name, e.size, e.hash);
  }
  for (const auto& n : names_) {
    std::uintmax_t size = 0;
    std::uint64_t hash = 0;
    if (!fingerprintOf(staging_ / n, size, hash)) throw OutputError((target_ / n).string() + ": cannot read back what was written");
    text += recordLine(n, size, hash);
  }
  write(kOutputsRecord, text);
  syncFileChecked((staging_ / kOutputsRecord).string());
  std::rotate(names_.begin(), names_.end() - 1, names_.end());  // the record moves in first
}

std::vector<std::string> OutputDir::targets() const {
  std::vector<std::string> out;
  for (const auto& n : names_)
    if (!own_only_ || n != kOutputsRecord) out.push_back((target_ / n).string());
  return out;
}

void OutputDir::commit() {
  MMV_DEMAND(!committed_);
  std::error_code ec;
  for (const auto& p : scratch_) fs::remove(p, ec);  // never part of the output; the staging must be empty of them
  scratch_.clear();
  // Every staged file is there in full and on the disk before any is placed (writers of
  // their own, PNG and .mat libraries, may have failed quietly).
  for (const auto& n : names_) syncFileChecked((staging_ / n).string());
  if (own_only_) stageRecord();
  for (const auto& n : names_) {
    const fs::path t = target_ / n;
    const fs::file_status st = fs::symlink_status(t, ec);
    if (!fs::exists(st)) continue;
    if (!force_) throw OutputError(t.string() + " exists: nothing was written (use --force to replace)");
    if (!fs::is_regular_file(st))
      throw OutputError(t.string() + " exists and is not a regular file (a directory or a link): nothing was written "
                                     "(--force replaces only the files mmvlab writes)");
  }
  created_target_ = !fs::exists(target_, ec);
  fs::create_directories(target_, ec);
  if (ec) throw OutputError(target_.string() + ": cannot create directory: " + ec.message());
  // --force: the old files are kept aside first and put back if any new one cannot be
  // placed (or anything after the commit fails, see the destructor), so a failure never
  // leaves the user with fewer files than before. A signal meanwhile waits for the end:
  // DIR then holds the whole new output (or, after a failure, the old one). Aside is a
  // second link to the old file, so the old name stays until the new file's rename
  // replaces it in one step: even a SIGKILL, which cannot be held, never leaves a name
  // missing (moving the old file aside left one for a moment; the signal test saw it).
  // A file system without hard links gets the move.
  const SignalsHeld held;
  committed_ = true;
  for (const auto& n : names_) {
    if (!fs::exists(fs::symlink_status(target_ / n, ec))) continue;
    fs::create_hard_link(target_ / n, staging_ / (".old-" + n), ec);
    if (ec) fs::rename(target_ / n, staging_ / (".old-" + n), ec);
    if (ec) {
      undoCommit();
      committed_ = false;
      throw OutputError((target_ / n).string() + ": cannot replace: " + ec.message());
    }
    aside_.push_back(n);
  }
  for (const auto& n : names_) {
    fs::rename(staging_ / n, target_ / n, ec);
    if (ec) {
      undoCommit();
      committed_ = false;
      throw OutputError((target_ / n).string() + ": cannot write: " + ec.message());
    }
    placed_.push_back(n);
  }
  // Committed: a signal from now on removes only the staging and the replaced files in it.
  forgetAll();
  remember(staging_, true);
  for (const auto& n : aside_) remember(staging_ / (".old-" + n), false);
}

}  // namespace mmv

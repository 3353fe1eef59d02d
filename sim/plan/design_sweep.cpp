// Parallel, resumable, sharded sweeps (sim/plan/design_sweep.hpp).
#include "sim/plan/design_sweep.hpp"

#include "sim/core/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/file.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <cmath>
#include <mutex>
#include <sstream>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {

namespace fs = std::filesystem;

std::string Shard::text() const { return strf("%d/%d", index, count); }

namespace {

constexpr const char* kJournal = "journal.csv";
constexpr const char* kMagic = "# mmvlab sweep journal v1";
constexpr const char* kLock = ".mmvlab-sweep.lock";
/// A journal holds at most kMaxSweepPoints rows of a few hundred bytes; a larger file is
/// not one of ours (docs/reliability.md, bounds table).
constexpr long kMaxJournalBytes = 1L << 30;

std::string headerLine(const std::vector<std::string>& header) {
  std::string s;
  for (std::size_t i = 0; i < header.size(); ++i) s += (i ? "," : "") + header[i];
  return s;
}

std::size_t fieldCount(const std::string& line) { return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1; }

/// The journal's identity line: fingerprint, points, shard.
std::string identity(const std::string& fingerprint, long total, const Shard& shard) {
  return std::string(kMagic) + " fingerprint=" + fingerprint + " points=" + std::to_string(total) + " shard=" + shard.text();
}

struct ParsedJournal {
  SweepJournal journal;
  std::uintmax_t valid_bytes = 0;  ///< where the well-formed part ends.
};

/// A row's cells after the point index hold numbers, words (ok, FAIL) or nothing; a
/// number that is not finite (nan, inf: a hand edit or another tool) is not one the
/// sweep writes, and its row is computed again.
bool cellsWellFormed(const std::string& line) {
  std::size_t start = line.find(',');
  while (start != std::string::npos) {
    const std::size_t end = line.find(',', start + 1);
    const std::string cell = line.substr(start + 1, end == std::string::npos ? std::string::npos : end - start - 1);
    char* stop = nullptr;
    const double v = std::strtod(cell.c_str(), &stop);
    if (!cell.empty() && stop == cell.c_str() + cell.size() && !std::isfinite(v)) return false;
    start = end;
  }
  return true;
}

ParsedJournal parseJournal(const fs::path& path) {
  std::string text, why;
  if (!readInputFile(path.string(), kMaxJournalBytes, text, why)) throw OutputError(path.string() + ": cannot read the sweep journal: " + why);
  ParsedJournal p;
  std::size_t pos = 0;
  auto nextLine = [&](std::string& line) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) return false;  // a torn last line has no newline
    line = text.substr(pos, nl - pos);
    pos = nl + 1;
    return true;
  };
  std::string id, header;
  if (!nextLine(id) || id.rfind(kMagic, 0) != 0 || !nextLine(header))
    throw OutputError(path.string() + ": not an mmvlab sweep journal (a file of the journal's name that no sweep wrote: "
                      "nothing was computed; move it or use another --out)");
  std::istringstream is(id.substr(std::string(kMagic).size()));
  std::string field;
  while (is >> field) {
    const auto eq = field.find('=');
    const std::string k = field.substr(0, eq), v = eq == std::string::npos ? "" : field.substr(eq + 1);
    if (k == "fingerprint") p.journal.fingerprint = v;
    if (k == "points") p.journal.total_points = std::atol(v.c_str());
    if (k == "shard" && std::sscanf(v.c_str(), "%d/%d", &p.journal.shard.index, &p.journal.shard.count) != 2)
      throw OutputError(path.string() + ": malformed shard '" + v + "'");
  }
  std::istringstream hs(header);
  while (std::getline(hs, field, ',')) p.journal.header.push_back(field);
  p.valid_bytes = pos;
  std::string line;
  while (nextLine(line)) {
    char* end = nullptr;
    const long point = std::strtol(line.c_str(), &end, 10);
    const bool ok = end != line.c_str() && *end == ',' && point >= 0 && point < p.journal.total_points &&
                    p.journal.shard.contains(point) && fieldCount(line) == p.journal.header.size() && !p.journal.rows.count(point) &&
                    cellsWellFormed(line);
    if (!ok) break;  // everything from here on is recomputed
    p.journal.rows.emplace(point, line);
    p.valid_bytes = pos;
  }
  return p;
}

/// Writes `text` to `path` through a temporary file and a rename: never half a file, and
/// no temporary left behind when the write or the rename fails.
void writeAtomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.parent_path() / ("." + path.filename().string() + ".tmp");
  std::error_code ec;
  try {
    writeFileChecked(tmp.string(), text);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw OutputError(path.string() + ": cannot write (" + why + ")");
  }
}

std::string tableText(const std::vector<std::string>& header, const std::map<long, std::string>& rows) {
  std::string s = headerLine(header) + "\n";
  for (const auto& [point, line] : rows) s += line + "\n";
  return s;
}

/// Appends rows to the journal, one write() per row, from any thread.
class JournalWriter {
 public:
  explicit JournalWriter(const fs::path& path) : fd_(::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC)) {
    if (fd_ < 0) throw OutputError(path.string() + ": cannot append to the sweep journal");
  }
  ~JournalWriter() { ::close(fd_); }
  void append(const std::string& line) {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string text = line + "\n";
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd_, text.data() + done, text.size() - done);
      if (n < 0) throw OutputError("cannot append to the sweep journal");
      done += static_cast<std::size_t>(n);
    }
  }

 private:
  int fd_;
  std::mutex mutex_;
};

/// The journal in `dir` for this run: read (resume) or created. `created` says this run
/// made it; a journal of another sweep that `restart` replaces is first set aside as
/// `aside` (put back by the caller if the run ends having computed nothing). Only the
/// sweep's own journal is ever replaced: a folder, link, device or FIFO in its place, or
/// a file that is not a sweep journal, is refused, with or without --force.
SweepJournal openJournal(const DesignSweepRun& run, bool restart, bool& created, fs::path& aside) {
  const fs::path path = fs::path(run.dir) / kJournal;
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(path, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw OutputError(path.string() + " is not a regular file (a folder, a link or a device), so not a sweep journal: "
                      "nothing was computed (--force replaces only the sweep's own journal)");
  if (fs::exists(st)) {
    ParsedJournal p = parseJournal(path);
    const bool same = p.journal.fingerprint == run.fingerprint && p.journal.header == run.header &&
                      p.journal.total_points == run.total_points;
    const bool same_shard = p.journal.shard.index == run.shard.index && p.journal.shard.count == run.shard.count;
    if (same && same_shard) {
      if (fs::file_size(path) != p.valid_bytes) fs::resize_file(path, p.valid_bytes);  // drop a torn or malformed tail
      return p.journal;
    }
    if (!restart && !same)
      throw OutputError(run.dir + " holds another sweep (its spec, scene or outputs differ): use another --out, or --force to start over");
    if (!restart)
      throw OutputError(run.dir + " holds shard " + p.journal.shard.text() + " of this sweep, not " + run.shard.text());
    aside = fs::path(run.dir) / (".journal.csv.old-" + std::to_string(::getpid()));
    fs::rename(path, aside, ec);
    if (ec) throw OutputError(path.string() + ": cannot set the old journal aside: " + ec.message());
  }
  writeAtomically(path, identity(run.fingerprint, run.total_points, run.shard) + "\n" + headerLine(run.header) + "\n");
  created = true;
  SweepJournal j;
  j.fingerprint = run.fingerprint;
  j.total_points = run.total_points;
  j.shard = run.shard;
  j.header = run.header;
  return j;
}

/// An exclusive lock on `dir` for this process's life in it: a second sweep on the same
/// --out (which would compute every point twice into one journal) is refused. The lock
/// file is removed when the sweep ends, well or not (while still locked: a sweep that
/// opened it meanwhile finds it unlinked and takes a new one).
class DirectoryLock {
 public:
  explicit DirectoryLock(const fs::path& dir) : path_(dir / kLock) {
    for (int attempt = 0;; ++attempt) {
      fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
      if (fd_ < 0) throw OutputError(path_.string() + ": cannot create the sweep's lock file");
      if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        char pid[32] = {0};
        const ssize_t n = ::pread(fd_, pid, sizeof pid - 1, 0);
        ::close(fd_);
        throw OutputError(dir.string() + " is in use by another sweep" + (n > 0 ? std::string(" (process ") + pid + ")" : std::string()) +
                          ": wait for it to finish, or use another --out");
      }
      // Locked: still the file at that name (not one its last holder removed meanwhile)?
      struct stat held{}, named{};
      if (::fstat(fd_, &held) == 0 && ::lstat(path_.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
          held.st_dev == named.st_dev)
        break;
      ::close(fd_);
      if (attempt == 100) throw OutputError(path_.string() + ": the sweep's lock file keeps changing");
    }
    const std::string me = std::to_string(::getpid());
    if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, me.data(), me.size(), 0) != static_cast<ssize_t>(me.size())) {
      // The pid is a courtesy for the message above; the lock itself is held.
    }
  }
  ~DirectoryLock() {
    ::unlink(path_.c_str());
    ::close(fd_);
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  fs::path path_;
  int fd_ = -1;
};

/// The folders a run creates (DIR, and OUT above a shard's DIR), removed again if the run
/// fails leaving them empty.
std::vector<fs::path> createFolders(const fs::path& dir) {
  std::vector<fs::path> made;
  std::error_code ec;
  for (fs::path p = fs::absolute(dir, ec); !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    made.push_back(p);
  fs::create_directories(dir, ec);
  if (!fs::is_directory(dir, ec)) {
    for (const auto& p : made) fs::remove(p, ec);
    throw OutputError(dir.string() + ": cannot create the output directory" + (ec ? ": " + ec.message() : std::string()));
  }
  return made;  // innermost first
}

}  // namespace

DesignSweepRunResult runDesignSweep(const DesignSweepRun& run, bool restart) {
  const auto t0 = std::chrono::steady_clock::now();
  MMV_DEMAND(!run.header.empty() && run.header.front() == "point" && run.shard.count >= 1 && run.jobs >= 1);
  const std::vector<fs::path> made = createFolders(run.dir);
  bool created = false;
  fs::path aside;
  long computed = 0;
  DesignSweepRunResult result;
  try {
    const DirectoryLock lock(run.dir);
    SweepJournal journal = openJournal(run, restart, created, aside);
    std::vector<long> todo;
    long in_shard = 0;
    for (long p = 0; p < run.total_points; ++p)
      if (run.shard.contains(p)) {
        ++in_shard;
        if (!journal.rows.count(p)) todo.push_back(p);
      }
    result.reused = in_shard - static_cast<long>(todo.size());
    std::atomic<long> done{result.reused};
    if (run.progress) run.progress(done, in_shard);
    std::mutex rows_mutex;
    {
      JournalWriter writer(fs::path(run.dir) / kJournal);
      tbb::task_arena arena(run.jobs);
      arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const std::vector<std::string> cells = run.evaluate(todo[i]);
            MMV_DEMAND(cells.size() + 1 == run.header.size());
            std::string line = std::to_string(todo[i]);
            for (const auto& c : cells) line += "," + c;
            writer.append(line);
            {
              std::lock_guard<std::mutex> lock(rows_mutex);
              journal.rows.emplace(todo[i], line);
              ++computed;
            }
            const long d = ++done;
            if (run.progress) run.progress(d, in_shard);
          }
        });
      });
    }
    result.computed = static_cast<long>(todo.size());
    result.csv = (fs::path(run.dir) / "sweep.csv").string();
    result.table = tableText(run.header, journal.rows);
  } catch (...) {
    // Nothing computed: the folder goes back as it was (the journal this run made or the
    // one it set aside, the folders it made). Points computed stay in the journal, which
    // the same command resumes.
    std::error_code ec;
    if (computed == 0) {
      if (created) fs::remove(fs::path(run.dir) / kJournal, ec);
      if (!aside.empty()) fs::rename(aside, fs::path(run.dir) / kJournal, ec);
      for (const auto& p : made) fs::remove(p, ec);  // only if empty
    } else if (!aside.empty()) {
      fs::remove(aside, ec);  // the new journal holds this run's points
    }
    throw;
  }
  std::error_code ec;
  if (!aside.empty()) fs::remove(aside, ec);  // the sweep it replaced is gone for good
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

SweepJournal readSweepJournal(const std::string& dir) {
  const fs::path path = fs::path(dir) / kJournal;
  if (!fs::exists(path)) throw OutputError(dir + ": no sweep journal here (not a `mmvlab sweep --out` directory)");
  return parseJournal(path).journal;
}

std::string mergeSweepTables(const std::vector<std::string>& dirs) {
  MMV_DEMAND(!dirs.empty());  // the command line requires at least one
  std::vector<SweepJournal> parts;
  for (const auto& d : dirs) parts.push_back(readSweepJournal(d));
  std::map<long, std::string> rows;
  std::map<long, std::string> owner;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SweepJournal& p = parts[i];
    if (p.fingerprint != parts[0].fingerprint || p.header != parts[0].header || p.total_points != parts[0].total_points)
      throw OutputError(dirs[i] + " is a shard of another sweep than " + dirs[0] + " (spec, scene or outputs differ)");
    for (const auto& [point, line] : p.rows) {
      if (owner.count(point)) throw OutputError(strf("point %ld is in both %s and %s", point, owner[point].c_str(), dirs[i].c_str()));
      owner[point] = dirs[i];
      rows[point] = line;
    }
  }
  std::vector<long> missing;
  for (long p = 0; p < parts[0].total_points; ++p)
    if (!rows.count(p)) missing.push_back(p);
  if (!missing.empty()) {
    std::string list;
    for (std::size_t i = 0; i < std::min<std::size_t>(missing.size(), 10); ++i) list += (i ? ", " : "") + std::to_string(missing[i]);
    throw OutputError(strf("%zu of %ld points are missing (%s%s): run the shards that hold them (or resume them) first", missing.size(),
                           parts[0].total_points, list.c_str(), missing.size() > 10 ? ", ..." : ""));
  }
  return tableText(parts[0].header, rows);
}

}  // namespace mmv

#pragma once
/// Running a sweep's points in parallel, resumably, in shards (docs/planning.md).
///
/// Every point is computed independently of the others (its value depends on its
/// index only), so serial, parallel and sharded runs write the same rows. Rows go to
/// DIR/journal.csv as they finish, one write() per row under a lock: a run killed at
/// any moment (SIGKILL included) leaves complete rows and at most one torn last line.
/// A new run in the same DIR checks that the journal belongs to the same sweep (its
/// fingerprint), drops a torn or malformed tail, skips the rows it has, and computes
/// the rest. When every point of the run's shard is in the journal, the table of
/// sweep.csv (rows sorted by point) is returned: the caller commits it with the rest of
/// the outputs (sim/app/design_sweep_study.hpp). A run that fails having computed no
/// point leaves DIR as it was (no journal, lock or temporary of its own, no folder it
/// made); one that computed points leaves them in the journal for a resume.
///
/// Parallelism: oneTBB's parallel_for in a task arena of `jobs` threads.

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace mmv {

/// A slice of the points: those with index % count == index_1based - 1.
struct Shard {
  int index = 1, count = 1;
  bool contains(long point) const { return point % count == index - 1; }
  std::string text() const;  ///< "I/N".
};

struct DesignSweepRun {
  std::string dir;
  std::string fingerprint;          ///< identifies the sweep (spec, scene, header, points).
  std::vector<std::string> header;  ///< the CSV header; the first column is "point".
  long total_points = 0;
  Shard shard;
  int jobs = 1;
  /// The cells of a point after its index (header.size() - 1 of them). Called from
  /// several threads at once. An exception stops the sweep (rows already written stay).
  std::function<std::vector<std::string>(long point)> evaluate;
  std::function<void(long done, long total)> progress;  ///< may be empty.
};

struct DesignSweepRunResult {
  long computed = 0, reused = 0;  ///< this run's points and those the journal already had.
  double seconds = 0;
  std::string csv;  ///< the path sweep.csv is committed to.
  std::string table;  ///< its contents.
};

/// Runs (or resumes) the sweep. Throws OutputError when DIR holds another sweep's
/// journal (a different fingerprint) unless `restart`, which replaces it (only once the
/// run has computed a point: until then the old one is set aside, and put back on a
/// failure); a journal.csv that is not a sweep journal (a user's file, a folder, a
/// link) is refused whatever `restart` says.
DesignSweepRunResult runDesignSweep(const DesignSweepRun& run, bool restart);

/// A finished shard (or whole sweep) directory as read back for merging.
struct SweepJournal {
  std::string fingerprint;
  long total_points = 0;
  Shard shard;
  std::vector<std::string> header;
  std::map<long, std::string> rows;  ///< point -> its CSV line (without newline).
};
/// Reads DIR/journal.csv (only its complete, well-formed rows). Throws OutputError if
/// there is none or it is not a journal.
SweepJournal readSweepJournal(const std::string& dir);

/// Joins shard directories into the table an unsharded run's sweep.csv holds. Throws
/// OutputError when the shards belong to different sweeps, overlap, or leave points
/// missing (named).
std::string mergeSweepTables(const std::vector<std::string>& dirs);

}  // namespace mmv

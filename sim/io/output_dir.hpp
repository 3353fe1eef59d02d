#pragma once
/// Writing a command's files into --out DIR as one transaction: every file is first
/// written into a private staging directory next to DIR (write(): every write, the
/// fsync and the close checked; files a library writes are checked and synced at
/// commit); commit() then checks that no file would replace one the user already has
/// (unless --force; a directory or anything but a regular file is never replaced) and
/// moves them all into DIR, the files they replace set aside. The transaction ends when
/// the OutputDir is destroyed: normally, the replaced files are dropped; while an
/// exception unwinds (anything after commit that fails, e.g. standard output that
/// cannot be written), DIR is put back as it was. If anything fails before commit(),
/// DIR is untouched and the staging directory is removed.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "sim/core/errors.hpp"

namespace mmv {

/// For a single output file written through a temporary beside it (`render --out`):
/// SIGINT, SIGTERM and SIGHUP remove `path` (until forgotten), as they remove OutputDir's
/// staging; and the temporaries `.mmvlab-PID-NAME` in `dir` whose process is gone (a
/// SIGKILL) are removed.
void removeOnSignal(const std::string& path);
void forgetRemovalsOnSignal();
void removeStaleTemporaries(const std::string& dir);

class OutputDir {
 public:
  OutputDir(const std::string& dir, bool force);
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  ~OutputDir();

  /// Where to write `name` now (inside the staging directory), for a writer of its own.
  std::string stage(const std::string& name);
  /// Where to write an intermediate file `name` that is not part of the output (a figure
  /// a report embeds): in the staging directory, removed with it and by the signal
  /// cleanup, never moved into DIR. Removed at commit().
  std::string scratch(const std::string& name);
  /// Writes `bytes` as `name` into the staging directory, every step checked.
  void write(const std::string& name, std::string_view bytes);
  /// Moves every staged file into the target directory. The files are reported on
  /// stderr ("mmvlab: wrote DIR/NAME") when the transaction ends well (the destructor).
  void commit();
  /// Where the staged files go (DIR/NAME), in the order they were staged.
  std::vector<std::string> targets() const;
  /// Reports the files as one line, "mmvlab: wrote N WHAT in DIR", instead of a line
  /// each (a run's hundreds of frames).
  void reportAsOne(std::string what) { report_as_ = std::move(what); }

 private:
  std::filesystem::path target_, staging_;
  std::vector<std::string> names_, scratch_;
  std::vector<std::string> aside_, placed_;  ///< replaced (kept in staging) and placed by commit()
  bool force_ = false, committed_ = false, created_target_ = false;
  std::string report_as_;  ///< reportAsOne's WHAT (empty: a line per file)
  int exceptions_at_start_ = 0;  ///< std::uncaught_exceptions() when made: more at the end means a failure
  void undoCommit();
};

}  // namespace mmv

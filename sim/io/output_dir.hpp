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

/// The record of the files mmvlab placed in a folder (OutputDir::replaceOnlyOwnFiles):
/// "# mmvlab outputs v1", then a line per file: its size, its FNV-1a 64-bit content hash
/// (hex) and its name.
inline constexpr const char* kOutputsRecord = ".mmvlab-outputs";

/// Before computing: throws OutputError naming the first of `names` that stands in `dir`
/// and is not, as it is now, a file of dir's record (a user's file, folder, link or FIFO
/// of an output's name); the record itself must be a regular file if it exists. Nothing
/// is written. A missing `dir` holds nothing.
void checkOwnOutputs(const std::string& dir, const std::vector<std::string>& names);

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
  /// Reports nothing on stderr (a library front end: Python).
  void reportNothing() { silent_ = true; }
  /// Replace only what mmvlab wrote here: commit() then replaces an existing file only
  /// if DIR's record of its outputs (kOutputsRecord: each file mmvlab placed there, with
  /// its size and content hash) lists it as it is now, with or without --force (a user's
  /// file of an output's name, or one they edited, is an OutputError and nothing is
  /// written), and writes the record of what it placed with the rest.
  void replaceOnlyOwnFiles() { own_only_ = true; }

 private:
  std::filesystem::path target_, staging_;
  std::vector<std::string> names_, scratch_;
  std::vector<std::string> aside_, placed_;  ///< replaced (kept in staging) and placed by commit()
  bool force_ = false, committed_ = false, created_target_ = false, silent_ = false, own_only_ = false;
  std::string report_as_;  ///< reportAsOne's WHAT (empty: a line per file)
  int exceptions_at_start_ = 0;  ///< std::uncaught_exceptions() when made: more at the end means a failure
  void undoCommit();
  void stageRecord();
};

}  // namespace mmv

#pragma once
// Internal to sim/cli: what `mmvlab render`'s still, mode and history frames share:
// the size option, the camera a view names, and files written whole or not at all.

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "renders/frame.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/files.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/scene/scene.hpp"

namespace mmv::cli {

/// The bounds on what render draws (docs/reliability.md, bounds table).
constexpr int kMaxFrameSide = 8192;             ///< --size, either side.
constexpr int kMaxMp4Side = 8191;               ///< MPEG-4 part 2 codes 13-bit dimensions.
constexpr double kMaxImagePixels = 8192.0 * 8192.0;  ///< one PNG, a contact sheet included.

/// "1280x720" -> width, height (16..8192 each; at most 8191 for an .mp4); UsageError otherwise.
/// A video's frames are drawn at 2x supersampling (stills: 3x): the encoder's
/// compression is coarser than the difference, and a 10 s run's video costs about a third
/// less (docs/benchmarks.md, "Renders").
inline constexpr int kVideoSupersample = 2;

void parseSize(const std::string& text, render::FrameOptions& o, const std::string& ext);
/// A contact sheet of `tiles` frames at most kMaxImagePixels; UsageError naming --mode and --size.
void checkSheetPixels(const std::string& size_text, const std::string& mode_text, std::size_t tiles, const render::FrameOptions& o);

/// The camera for `--view VIEW` on drawing `d`: a preset framing `frame` (the drawing's
/// own bounds when empty), `lab` (the whole room), `sensor:NAME`, or a scene view.
/// UsageError for an unknown view.
Camera chooseCamera(const std::string& view, const DrawList& d, const std::vector<CameraView>& views,
                    const Eigen::AlignedBox3d& frame = Eigen::AlignedBox3d());

/// Writes through a temporary name in the same directory, renamed on success, so a
/// failed or interrupted run leaves no partial file (SIGINT, SIGTERM, SIGHUP remove the
/// temporary; one a SIGKILL left is removed by the next run writing there); refuses to
/// replace a file unless `force` (OutputError, exit 73). A failure while writing is an
/// OutputError unless it has an exit code of its own (usage, numerical, unavailable,
/// internal).
/// The checks writeAtomically makes before it writes, made before any drawing too: an
/// existing file only with `force`, and never anything but a regular file (a link, a
/// FIFO, a device or a folder of that name: --force replaces only a file).
inline void checkOutputFile(const std::string& path, bool force) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  const fs::file_status st = fs::symlink_status(target, ec);
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw OutputError(path + ": exists and is not a regular file (a link, a FIFO, a device or a folder): nothing was "
                             "written (--force replaces only a file)");
  if (fs::exists(st) && !force) throw OutputError(path + ": exists (use --force to replace it)");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw OutputError(path + ": the directory " + dir.string() + " does not exist");
}

template <class Write>
void writeAtomically(const std::string& path, bool force, Write write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  std::error_code ec;
  checkOutputFile(path, force);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  removeStaleTemporaries(dir.string());
  const fs::path tmp = dir / (".mmvlab-" + std::to_string(::getpid()) + "-" + target.filename().string());
  removeOnSignal(tmp.string());
  struct Forget {
    ~Forget() { forgetRemovalsOnSignal(); }
  } forget;
  try {
    write(tmp.string());
    syncFileChecked(tmp.string());  // there, whole and on the disk before it is renamed
  } catch (...) {
    fs::remove(tmp, ec);
    // An error with an exit code of its own keeps it (a missing video plugin is 69, not
    // 73); whatever else failed while writing is the output's.
    try {
      throw;
    } catch (const UsageError&) {
      throw;
    } catch (const NumericalError&) {
      throw;
    } catch (const UnavailableError&) {
      throw;
    } catch (const InternalError&) {
      throw;
    } catch (const std::exception& e) {
      throw OutputError(e.what());
    }
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw OutputError(path + ": cannot write (" + ec.message() + ")");
  }
}

}  // namespace mmv::cli

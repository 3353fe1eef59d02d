#pragma once
/// The mmvlab subcommands: each wires a scene to an analysis and a writer. Output is
/// composed completely in memory and written only on success, so a failing run
/// writes nothing to stdout; diagnostics go to stderr.

#include <string>

namespace mmv::cli {

/// Exit codes (sysexits.h where one fits).
enum ExitCode : int {
  kOk = 0,
  kNumericalFailure = 1,  ///< the analysis could not produce trustworthy numbers.
  kUsage = 64,            ///< bad command line.
  kDataError = 65,        ///< bad scene content.
  kNoInput = 66,          ///< the scene file is missing or unreadable.
  kInternal = 70,         ///< a bug: please report it.
};

struct SceneArgs {
  std::string scene_path;  ///< empty: the embedded default scene.
  int segments = 0;        ///< > 0: override every flexible link's segment count.
};

struct ModesArgs : SceneArgs {
  bool json = false;
  int modes = 12;  ///< modes to report; 0 = all.
};

struct ConvergeArgs : SceneArgs {
  bool json = false;
  int max_segments = 64;
  int modes = 6;
};

int runModesCommand(const ModesArgs& args);
int runConvergeCommand(const ConvergeArgs& args);
int runSceneCommand();

}  // namespace mmv::cli

#pragma once
// What a long computation is doing now, for whoever watches it: the CLI's watchdog
// prints it on stderr every 15 s (sim/cli/progress.hpp), so a run of minutes is never
// taken for a hang. The work names its stages (RAII, nested: "modes" > "eigen-solution
// (4096 DOF)") and counts inside the innermost one ("mode 3 of 12"); recording is cheap
// (a mutex, no I/O) and nothing is printed here.
//
// Stages are recorded from one thread: the one that opened the outermost stage (the
// command's); stages opened on worker threads (a sweep's points) are ignored, the sweep
// counts its points itself. Counts come from any thread (a parallel loop's workers).
#include <chrono>
#include <string>
#include <vector>

namespace mmv {

struct ProgressState;

/// This module's state; a plugin (the figures) reports into its host's by adopting it.
ProgressState* progressState();
void adoptProgressState(ProgressState* host);

class ProgressStage {
 public:
  explicit ProgressStage(std::string what);
  ~ProgressStage();
  ProgressStage(const ProgressStage&) = delete;
  ProgressStage& operator=(const ProgressStage&) = delete;

 private:
  bool recorded_ = false;
};

/// `done` of `total` within the innermost stage ("point 3 of 200"); each stage keeps
/// its own count while stages inside it come and go.
void progressCount(long done, long total, const char* unit = "");

struct ProgressLevel {
  std::string what;
  long done = 0, total = 0;
  std::string unit;
  std::chrono::steady_clock::time_point opened{};  ///< when the stage opened: its pace, so its time left
};

/// The time left in a stage that counts, at its pace so far ("about 40 s left"); empty
/// before a second of it or its first count.
std::string progressTimeLeft(const ProgressLevel& l, std::chrono::steady_clock::time_point now);
/// The open stages, outermost first.
std::vector<ProgressLevel> progressSnapshot();

/// A host's check, run on the recording thread whenever a stage opens or a count is
/// recorded there (the Python module: its signals, so Ctrl-C ends a long run between two
/// steps, and the user's progress callback). It may throw to abandon the work: what the
/// work holds is released by unwinding, as for any error. Empty: none (the CLI's).
using ProgressCheckpoint = void (*)();
void setProgressCheckpoint(ProgressCheckpoint check);

}  // namespace mmv

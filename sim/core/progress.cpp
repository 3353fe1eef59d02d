#include "sim/core/progress.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <thread>

namespace mmv {

struct ProgressState {
  std::mutex mutex;
  std::thread::id owner;
  std::vector<ProgressLevel> stages;
};

namespace {

ProgressState own;
ProgressState* state = &own;
std::atomic<ProgressCheckpoint> checkpoint{nullptr};

/// The checkpoint, on the recording thread only (not a worker's), outside the lock.
void runCheckpoint(const ProgressState& s) {
  const ProgressCheckpoint check = checkpoint.load();
  if (check && s.owner == std::this_thread::get_id()) check();
}

}  // namespace

ProgressState* progressState() { return state; }
void adoptProgressState(ProgressState* host) { state = host ? host : &own; }

ProgressStage::ProgressStage(std::string what) {
  ProgressState& s = *state;
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.stages.empty()) s.owner = std::this_thread::get_id();
    else if (s.owner != std::this_thread::get_id()) return;
    s.stages.push_back({std::move(what), 0, 0, "", std::chrono::steady_clock::now()});
    recorded_ = true;
  }
  try {
    runCheckpoint(s);  // sees the stage just opened
  } catch (...) {
    std::lock_guard<std::mutex> lock(s.mutex);
    s.stages.pop_back();  // no destructor runs for a constructor that throws
    recorded_ = false;
    throw;
  }
}

ProgressStage::~ProgressStage() {
  if (!recorded_) return;
  ProgressState& s = *state;
  std::lock_guard<std::mutex> lock(s.mutex);
  if (s.stages.empty()) return;
  // MMVLAB_STAGE_TIMES: each stage's wall time on stderr as it closes, indented by depth
  // (docs/benchmarks.md: where a command's time goes, without a profiler).
  static const bool timed = std::getenv("MMVLAB_STAGE_TIMES") != nullptr;
  if (timed) {
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - s.stages.back().opened).count();
    std::fprintf(stderr, "mmvlab: stage %*s%.1f ms  %s\n", static_cast<int>(2 * (s.stages.size() - 1)), "", ms,
                 s.stages.back().what.c_str());
  }
  s.stages.pop_back();
}

void progressCount(long done, long total, const char* unit) {
  ProgressState& s = *state;
  {
    std::lock_guard<std::mutex> lock(s.mutex);
    if (s.stages.empty()) return;
    ProgressLevel& l = s.stages.back();
    l.done = done;
    l.total = total;
    l.unit = unit ? unit : "";
  }
  runCheckpoint(s);
}

void setProgressCheckpoint(ProgressCheckpoint check) { checkpoint.store(check); }

std::string progressTimeLeft(const ProgressLevel& l, std::chrono::steady_clock::time_point now) {
  const double spent = std::chrono::duration<double>(now - l.opened).count();
  if (l.done <= 0 || l.total <= l.done || spent < 1.0) return "";
  const double left = spent * static_cast<double>(l.total - l.done) / static_cast<double>(l.done);
  char text[48];
  if (left < 90) std::snprintf(text, sizeof text, "about %.0f s left", std::max(1.0, left));
  else std::snprintf(text, sizeof text, "about %.0f min left", left / 60);
  return text;
}

std::vector<ProgressLevel> progressSnapshot() {
  ProgressState& s = *state;
  std::lock_guard<std::mutex> lock(s.mutex);
  return s.stages;
}

}  // namespace mmv

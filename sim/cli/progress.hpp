#pragma once
// Progress of a long command on standard error, so a slow run is never taken for a hang:
// on a terminal a bar redrawn in place after the first second; off a terminal (a log
// file, CI, a pipe) one plain line every 15 s of wall time after the first 15 s. A
// watchdog thread does the printing, so the lines keep coming even while one step of
// the work (one sample interval of a stiff time run) takes minutes. Short runs print
// nothing; standard output (the results) is never touched.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace mmv::cli {

class Progress {
 public:
  /// `what` names the quantity counted: "time run, seconds simulated".
  explicit Progress(std::string what);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// `done` of `total` (same unit), `detail` what is being done now (may be empty).
  /// Thread-safe and cheap: it only records; the watchdog prints.
  void report(double done, double total, const std::string& detail = "");

 private:
  void watch();
  void print(double elapsed);

  const std::string what_;
  const bool tty_;
  const std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false, bar_shown_ = false;
  double done_ = 0, total_ = 0, last_line_ = 0;
  std::string detail_;
  std::thread thread_;
};

/// The command's watchdog (one, made by main): every 15 s of a run (the first line at
/// 15 s; MMVLAB_PROGRESS_INTERVAL=SECONDS changes it, for the tests) it prints the
/// stages the work has named (sim/core/progress.hpp), for example
///   mmvlab: still working (30 s): sweep-config > configurations of the grid (configuration 3 of 40) > eigen-solution: 12 modes of 64 DOF
/// unless a Progress bar of its own is reporting. Short runs print nothing.
class Watchdog {
 public:
  Watchdog();
  ~Watchdog();
  Watchdog(const Watchdog&) = delete;
  Watchdog& operator=(const Watchdog&) = delete;

 private:
  void watch();
  const double interval_;
  const std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread thread_;
};

}  // namespace mmv::cli

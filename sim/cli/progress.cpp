#include "sim/cli/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>

#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {

namespace {

std::atomic<int> bars{0};  ///< Progress objects alive: they report, the watchdog keeps quiet.

double watchdogInterval() {
  const char* v = std::getenv("MMVLAB_PROGRESS_INTERVAL");
  if (!v) return 15.0;
  char* end = nullptr;
  const double s = std::strtod(v, &end);
  return end != v && *end == '\0' && s > 0 && s < 1e6 ? s : 15.0;
}

}  // namespace

Watchdog::Watchdog() : interval_(watchdogInterval()), start_(std::chrono::steady_clock::now()), thread_([this] { watch(); }) {}

Watchdog::~Watchdog() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Watchdog::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  double next = interval_;
  const auto tick = std::chrono::duration<double>(std::min(1.0, interval_ / 4));
  while (!wake_.wait_for(lock, tick, [this] { return stop_; })) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < next) continue;
    next = elapsed + interval_;
    if (bars.load() > 0) continue;
    std::string where;
    const auto now = std::chrono::steady_clock::now();
    for (const ProgressLevel& l : progressSnapshot()) {
      where += (where.empty() ? "" : " > ") + printable(l.what);
      const std::string left = progressTimeLeft(l, now);
      if (l.total > 0)
        where += strf(" (%s%s%ld of %ld%s%s)", l.unit.c_str(), l.unit.empty() ? "" : " ", l.done, l.total, left.empty() ? "" : ", ",
                      left.c_str());
    }
    std::fprintf(stderr, elapsed < 10 ? "mmvlab: still working (%.1f s)%s%s\n" : "mmvlab: still working (%.0f s)%s%s\n", elapsed, where.empty() ? "" : ": ", where.c_str());
    std::fflush(stderr);
  }
}

Progress::Progress(std::string what)
    : what_(std::move(what)), tty_(::isatty(STDERR_FILENO) != 0), start_(std::chrono::steady_clock::now()),
      thread_([this] { watch(); }) {
  ++bars;
}

Progress::~Progress() {
  --bars;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  thread_.join();
  if (bar_shown_) {  // the bar's last state, then its line ends
    print(std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    std::fprintf(stderr, "\n");
  }
}

void Progress::report(double done, double total, const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  done_ = done, total_ = total, detail_ = detail;
}

void Progress::watch() {
  const double interval = watchdogInterval();
  const auto tick = std::chrono::duration<double>(tty_ ? 0.25 : std::min(1.0, interval / 4));
  std::unique_lock<std::mutex> lock(mutex_);
  while (!wake_.wait_for(lock, tick, [this] { return stop_; })) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (!(total_ > 0)) continue;
    if (tty_ && elapsed >= 1.0) {
      bar_shown_ = true;
      print(elapsed);
    } else if (!tty_ && elapsed >= interval && elapsed - last_line_ >= interval) {
      last_line_ = elapsed;
      print(elapsed);
    }
  }
}

// Called with the mutex held (or after the watchdog has stopped).
void Progress::print(double elapsed) {
  const double f = std::clamp(done_ / total_, 0.0, 1.0);
  const std::string left = f > 0 ? strf("about %.0f s left", elapsed * (1 - f) / f) : std::string("time left unknown");
  const std::string detail = detail_.empty() ? "" : ": " + printable(detail_);
  if (tty_) {
    std::fprintf(stderr, "\r[%-30s] %5.1f %% %s, %s%s\x1b[K", std::string(static_cast<std::size_t>(30 * f), '#').c_str(),
                 100 * f, what_.c_str(), left.c_str(), detail.c_str());
  } else {
    std::fprintf(stderr, "mmvlab: %s: %g of %g (%.0f %%), %.0f s elapsed, %s%s\n", what_.c_str(), done_, total_, 100 * f,
                 elapsed, left.c_str(), detail.c_str());
  }
  std::fflush(stderr);
}

}  // namespace mmv::cli

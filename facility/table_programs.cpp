#include "facility/table_programs.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

namespace mmv::facility {
namespace {

class Sine : public TableProgram {
 public:
  Sine(double a, double f, double T, double ramp) : a_(a), w_(2 * M_PI * f), T_(T), ramp_(ramp) {}
  double position(double t) const override {
    double e, de, dde;
    envelope(t, e, de, dde);
    return a_ * e * std::sin(w_ * t);
  }
  double velocity(double t) const override {
    double e, de, dde;
    envelope(t, e, de, dde);
    return a_ * (de * std::sin(w_ * t) + e * w_ * std::cos(w_ * t));
  }
  double acceleration(double t) const override {
    double e, de, dde;
    envelope(t, e, de, dde);
    return a_ * ((dde - e * w_ * w_) * std::sin(w_ * t) + 2 * de * w_ * std::cos(w_ * t));
  }
  double duration() const override { return T_; }
  double maxFrequencyHz() const override { return w_ / (2 * M_PI); }
  std::string describe() const override {
    std::ostringstream os;
    os << "sine dwell " << a_ << " m at " << w_ / (2 * M_PI) << " Hz";
    if (ramp_ > 0) os << " (raised-cosine ramp-in over " << ramp_ << " s)";
    return os.str();
  }

 private:
  /// Amplitude envelope: 1/2 (1 - cos(pi t / ramp)) during the ramp, then 1, so the
  /// motion starts from rest with zero acceleration instead of a velocity jump.
  void envelope(double t, double& e, double& de, double& dde) const {
    if (ramp_ <= 0 || t >= ramp_) {
      e = 1, de = 0, dde = 0;
      return;
    }
    if (t <= 0) {
      e = 0, de = 0, dde = 0;
      return;
    }
    const double k = M_PI / ramp_;
    e = 0.5 * (1 - std::cos(k * t));
    de = 0.5 * k * std::sin(k * t);
    dde = 0.5 * k * k * std::cos(k * t);
  }
  double a_, w_, T_, ramp_;
};

class Sweep : public TableProgram {
 public:
  Sweep(double a, double f0, double f1, double T, bool log) : a_(a), f0_(f0), f1_(f1), T_(T), log_(log) {}
  // Phase, its rate and its acceleration: phi, phi', phi''.
  /// Outside [0, T] the sweep dwells at its end frequencies with a continuous phase, so
  /// position, velocity and acceleration stay one motion (clamping t alone held the
  /// position while the velocity went on: a contradiction the integrators crawled through).
  void phase(double t, double& p, double& dp, double& ddp) const {
    if (t < 0) {
      p = 2 * M_PI * f0_ * t, dp = 2 * M_PI * f0_, ddp = 0;
      return;
    }
    if (t > T_) {
      phase(T_, p, dp, ddp);
      p += 2 * M_PI * f1_ * (t - T_), dp = 2 * M_PI * f1_, ddp = 0;
      return;
    }
    if (log_) {
      const double k = std::log(f1_ / f0_) / T_;
      p = 2 * M_PI * f0_ * (std::exp(k * t) - 1) / k;
      dp = 2 * M_PI * f0_ * std::exp(k * t);
      ddp = k * dp;
    } else {
      const double c = (f1_ - f0_) / T_;
      p = 2 * M_PI * (f0_ * t + 0.5 * c * t * t);
      dp = 2 * M_PI * (f0_ + c * t);
      ddp = 2 * M_PI * c;
    }
  }
  double position(double t) const override {
    double p, dp, ddp;
    phase(t, p, dp, ddp);
    return a_ * std::sin(p);
  }
  double velocity(double t) const override {
    double p, dp, ddp;
    phase(t, p, dp, ddp);
    return a_ * dp * std::cos(p);
  }
  double acceleration(double t) const override {
    double p, dp, ddp;
    phase(t, p, dp, ddp);
    return a_ * (ddp * std::cos(p) - dp * dp * std::sin(p));
  }
  double duration() const override { return T_; }
  double maxFrequencyHz() const override { return std::max(f0_, f1_); }
  std::string describe() const override {
    std::ostringstream os;
    os << (log_ ? "log" : "linear") << " sine sweep " << a_ << " m, " << f0_ << " to " << f1_ << " Hz in " << T_ << " s";
    return os.str();
  }

 private:
  double a_, f0_, f1_, T_;
  bool log_;
};

class Random : public TableProgram {
 public:
  Random(double rms, double flo, double fhi, double T, std::uint64_t seed, int n) : T_(T), fhi_(fhi) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> phase(0, 2 * M_PI);
    amp_ = rms * std::sqrt(2.0 / n);  // each line contributes amp^2/2 to the mean square
    for (int i = 0; i < n; ++i) {
      w_.push_back(2 * M_PI * (n > 1 ? flo + (fhi - flo) * i / (n - 1) : flo));
      phi_.push_back(phase(rng));
    }
  }
  double position(double t) const override { return sum(t, 0); }
  double velocity(double t) const override { return sum(t, 1); }
  double acceleration(double t) const override { return sum(t, 2); }
  double duration() const override { return T_; }
  double maxFrequencyHz() const override { return fhi_; }
  std::string describe() const override { return "band-limited random"; }

 private:
  double sum(double t, int d) const {
    double x = 0;
    for (std::size_t i = 0; i < w_.size(); ++i) {
      const double a = w_[i] * t + phi_[i];
      x += d == 0 ? std::sin(a) : d == 1 ? w_[i] * std::cos(a) : -w_[i] * w_[i] * std::sin(a);
    }
    return amp_ * x;
  }
  double T_, fhi_, amp_ = 0;
  std::vector<double> w_, phi_;
};

/// A profile's samples and the slopes of its cubic Hermite pieces, shared by every
/// program made from the same text (a model is built once per run, pilot and sweep
/// point; the text is parsed once).
struct ProfileSamples {
  std::vector<double> t, x, m;
  double fmax = 0;
  ProfileSamples(std::vector<double> times, std::vector<double> values) : t(std::move(times)), x(std::move(values)) {
    const std::size_t n = t.size();
    m.assign(n, 0.0);
    for (std::size_t i = 1; i + 1 < n; ++i) m[i] = (x[i + 1] - x[i - 1]) / (t[i + 1] - t[i - 1]);
    double shortest = INFINITY;
    for (std::size_t i = 1; i < n; ++i) shortest = std::min(shortest, t[i] - t[i - 1]);
    fmax = 0.5 / shortest;  // the samples cannot carry more than their Nyquist frequency
  }
};

class Profile : public TableProgram {
 public:
  explicit Profile(std::shared_ptr<const ProfileSamples> samples) : s_(std::move(samples)) {}
  // Cubic Hermite on [t_i, t_i+1]; derivative order d.
  double eval(double t, int d) const {
    const std::vector<double>&t_ = s_->t, &x_ = s_->x, &m_ = s_->m;
    if (t <= t_.front()) return d == 0 ? x_.front() : 0.0;
    if (t >= t_.back()) return d == 0 ? x_.back() : 0.0;
    const std::size_t i = std::upper_bound(t_.begin(), t_.end(), t) - t_.begin() - 1;
    const double h = t_[i + 1] - t_[i], s = (t - t_[i]) / h;
    const double p0 = x_[i], p1 = x_[i + 1], m0 = m_[i] * h, m1 = m_[i + 1] * h;
    if (d == 0)
      return (2 * s * s * s - 3 * s * s + 1) * p0 + (s * s * s - 2 * s * s + s) * m0 + (-2 * s * s * s + 3 * s * s) * p1 +
             (s * s * s - s * s) * m1;
    if (d == 1)
      return ((6 * s * s - 6 * s) * p0 + (3 * s * s - 4 * s + 1) * m0 + (-6 * s * s + 6 * s) * p1 + (3 * s * s - 2 * s) * m1) / h;
    return ((12 * s - 6) * p0 + (6 * s - 4) * m0 + (-12 * s + 6) * p1 + (6 * s - 2) * m1) / (h * h);
  }
  double position(double t) const override { return eval(t, 0); }
  double velocity(double t) const override { return eval(t, 1); }
  double acceleration(double t) const override { return eval(t, 2); }
  double duration() const override { return s_->t.back(); }
  double maxFrequencyHz() const override { return s_->fmax; }
  std::string describe() const override { return "profile of " + std::to_string(s_->t.size()) + " samples"; }

 private:
  std::shared_ptr<const ProfileSamples> s_;
};

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

std::unique_ptr<TableProgram> sineDwell(double a, double f, double T, double ramp) {
  require(f > 0 && T > 0 && std::isfinite(a) && ramp >= 0, "sine dwell: frequency and duration must be > 0, ramp >= 0");
  return std::make_unique<Sine>(a, f, T, ramp);
}

std::unique_ptr<TableProgram> sineSweep(double a, double f0, double f1, double T, bool log) {
  require(f0 > 0 && f1 > 0 && T > 0 && std::isfinite(a), "sine sweep: frequencies and duration must be > 0");
  return std::make_unique<Sweep>(a, f0, f1, T, log);
}

std::unique_ptr<TableProgram> bandLimitedRandom(double rms, double flo, double fhi, double T, std::uint64_t seed, int n) {
  require(rms >= 0 && flo > 0 && fhi > flo && T > 0 && n >= 1, "random: need rms >= 0, 0 < f_lo < f_hi, duration > 0");
  return std::make_unique<Random>(rms, flo, fhi, T, seed, n);
}

namespace {

std::shared_ptr<const ProfileSamples> parseProfile(const std::string& text, const std::string& source) {
  std::istringstream is(text);
  std::string line;
  int no = 0;
  auto fail = [&](const std::string& what) { throw std::invalid_argument(source + ":" + std::to_string(no) + ": " + what); };
  if (!std::getline(is, line)) fail("empty profile (expected the header time_s,x_m)");
  ++no;
  if (line.rfind("time_s,x_m", 0) != 0 && line.rfind("time_s,torque_n_m", 0) != 0 && line.rfind("time_s,angle_deg", 0) != 0 &&
      line.rfind("time_s,force_n", 0) != 0)
    fail("header must be time_s,x_m (time_s,torque_n_m for a torque, time_s,angle_deg for an angle program, time_s,force_n "
         "for the shaker's force) (got " + line + ")");
  std::vector<double> t, x;
  while (std::getline(is, line)) {
    ++no;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto comma = line.find(',');
    if (comma == std::string::npos) fail("expected two numbers, time_s,x_m (got " + line + ")");
    char *e1 = nullptr, *e2 = nullptr;
    const std::string a = line.substr(0, comma), b = line.substr(comma + 1);
    const double tv = std::strtod(a.c_str(), &e1), xv = std::strtod(b.c_str(), &e2);
    auto trailing = [](const char* e) { return std::string(e).find_first_not_of(" \t\r") != std::string::npos; };
    if (e1 == a.c_str() || e2 == b.c_str() || trailing(e1) || trailing(e2) || !std::isfinite(tv) || !std::isfinite(xv))
      fail("expected two numbers, time_s,x_m (got " + line + ")");
    if (!t.empty() && !(tv > t.back())) fail("times must increase (got " + a + " after " + std::to_string(t.back()) + ")");
    t.push_back(tv);
    x.push_back(xv);
  }
  if (t.size() < 2) fail("a profile needs at least two samples");
  return std::make_shared<const ProfileSamples>(std::move(t), std::move(x));
}

}  // namespace

std::unique_ptr<TableProgram> csvProfile(const std::string& text, const std::string& source) {
  // The last few texts parsed, by content (a text that fails is never kept, so its error
  // names the source of each call); threads of a sweep share it.
  static std::mutex mutex;
  static std::vector<std::pair<std::string, std::shared_ptr<const ProfileSamples>>> parsed;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    for (const auto& [kept, samples] : parsed)
      if (kept == text) return std::make_unique<Profile>(samples);
  }
  std::shared_ptr<const ProfileSamples> samples = parseProfile(text, source);
  const std::lock_guard<std::mutex> lock(mutex);
  if (parsed.size() >= 4) parsed.erase(parsed.begin());
  parsed.emplace_back(text, samples);
  return std::make_unique<Profile>(std::move(samples));
}

ProgramCheck checkProgram(const TableProgram& p, const TableSpec& table, double horizon) {
  ProgramCheck c;
  const double span = horizon > 0 ? std::min(horizon, p.duration()) : p.duration();
  const double f = std::max(p.maxFrequencyHz(), 1e-3);
  // 20 points per period, and never fewer than 400 in all, up to 2e6.
  const int n = static_cast<int>(std::min(2e6, std::max(400.0, std::ceil(20 * f * span) + 1)));
  for (int k = 0; k <= n; ++k) {
    const double t = span * k / n;
    c.peak_displacement = std::max(c.peak_displacement, std::abs(p.position(t)));
    c.peak_acceleration = std::max(c.peak_acceleration, std::abs(p.acceleration(t)));
  }
  std::ostringstream os;
  if (c.peak_displacement > table.stroke) {
    c.within_stroke = false;
    os << p.describe() << ": peak displacement " << c.peak_displacement << " m exceeds the table's +-" << table.stroke
       << " m stroke";
    c.messages.push_back(os.str());
    os.str("");
  }
  if (p.maxFrequencyHz() > table.bandwidth_hz) {
    c.above_bandwidth = true;
    os << p.describe() << ": content up to " << p.maxFrequencyHz() << " Hz, above the table's " << table.bandwidth_hz
       << " Hz bandwidth: the servo will attenuate it";
    c.messages.push_back(os.str());
  }
  return c;
}

}  // namespace mmv::facility

#include "sim/scene/programs.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

namespace mmv {

std::shared_ptr<const facility::TableProgram> makeTableProgram(const TableMotion& m) {
  switch (m.type) {
    case TableMotion::Type::Sine:  // a dwell lasts as long as the run: no end of its own
      return facility::sineDwell(m.amplitude, m.frequency_hz, std::numeric_limits<double>::max(), m.ramp);
    case TableMotion::Type::Sweep: return facility::sineSweep(m.amplitude, m.from_hz, m.to_hz, m.duration, m.logarithmic);
    case TableMotion::Type::Random:
      return facility::bandLimitedRandom(m.rms, m.from_hz, m.to_hz, m.duration, m.seed);
    case TableMotion::Type::Profile: return facility::csvProfile(m.profile_csv, m.profile_source);
  }
  return nullptr;
}

facility::Slew makeSlew(const SlewSpec& spec, double from, double range, bool continuous) {
  if (spec.spin_rate != 0) {
    if (!continuous)
      throw std::invalid_argument("a spin-up turns past any angle: it needs range_deg: unlimited (a slip ring), not a +-" +
                                  std::to_string(static_cast<int>(std::lround(range * 180 / M_PI))) + " deg travel");
    return facility::makeSpinUp(from, spec.spin_rate, spec.spin_ramp);
  }
  if (!spec.program_csv.empty())
    return facility::makeAngleProgram(from, facility::csvProfile(spec.program_csv, spec.program_source), M_PI / 180,
                                      continuous ? INFINITY : range);
  const facility::SlewLimits limits{continuous ? INFINITY : range, spec.max_rate, spec.max_acceleration};
  return facility::makeSlew(spec.trapezoidal ? facility::SlewShape::Trapezoidal : facility::SlewShape::Cycloidal, from,
                            spec.to, spec.start_time, limits);
}

std::vector<SlewTiming> slewTimings(const ArticleSpec& article) {
  std::vector<SlewTiming> out;
  const auto add = [&](const std::string& axis, const char* group, const SlewSpec& slew, double from, double range, bool continuous) {
    out.push_back({axis, group, slew.start_time, slew.start_time + makeSlew(slew, from, range, continuous).duration()});
  };
  for (const auto& j : article.joints)
    if (j.slew) add(j.name, "torquers", *j.slew, j.angle, j.range, j.continuous);
  if (const auto& g = article.base.gimbal) {
    const std::pair<const char*, const GimbalAxisSpec*> gimbal[] = {{"gimbal.yaw", &g->yaw}, {"gimbal.pitch", &g->pitch}, {"gimbal.roll", &g->roll}};
    for (const auto& [name, a] : gimbal)
      if (a->slew) add(name, "gimbal", *a->slew, a->angle, a->range, a->continuous);
  }
  return out;
}

std::string slewOutsideRun(const SlewTiming& t, double duration) {
  char buf[320];
  if (t.start_s >= duration)
    std::snprintf(buf, sizeof buf, "it starts at %.4g s, at or after the run's end at %.4g s: the run never shows it; move start_s "
                                   "or lengthen simulation.duration", t.start_s, duration);
  else if (t.end_s > duration)
    std::snprintf(buf, sizeof buf, "from %.4g s to %.4g s, past the run's end at %.4g s: the run shows only its start; lengthen "
                                   "simulation.duration", t.start_s, t.end_s, duration);
  else
    return "";
  return buf;
}

}  // namespace mmv

#include "sim/modes/converge.hpp"

#include <chrono>
#include <algorithm>
#include <cmath>
#include <map>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

ConvergenceMode assessLadder(ModeNumber number, const std::vector<double>& frequency_hz) {
  ConvergenceMode m;
  m.number = number;
  m.frequency_hz = frequency_hz;
  const std::size_t nr = frequency_hz.size();
  if (nr < 2 || !std::isfinite(frequency_hz[nr - 1]) || !std::isfinite(frequency_hz[nr - 2])) return m;
  const double f1 = frequency_hz[nr - 1], f2 = frequency_hz[nr - 2];
  m.has_estimate = true;
  m.extrapolated_hz = f1 + (f1 - f2) / 3.0;
  m.estimated_relative_error = std::abs(f1 - m.extrapolated_hz) / std::abs(m.extrapolated_hz);
  if (nr < 3 || !std::isfinite(frequency_hz[nr - 3])) return m;
  const double f3 = frequency_hz[nr - 3];
  const double ratio = (f3 - f2) / (f2 - f1);
  m.check = "unconverged";
  if (std::isfinite(ratio) && ratio > 0) {
    m.has_observed_order = true;
    m.observed_order = std::log2(ratio);
    if (std::abs(m.observed_order - 2.0) <= 0.5)
      m.check = "ok";
    else if (m.observed_order > 0.5)
      m.check = "order";
  }
  // An order above the scheme's 2 comes from meshes short of the asymptotic range: it
  // may not shrink the estimate below Richardson's (the spatial article at 1, 2 and 4
  // segments shows 2.8 and is 1.5 % off, not the 0.8 % that order would claim).
  if (m.check == "order")
    m.estimated_relative_error =
        std::abs(f1 - f2) / (std::pow(2.0, std::min(m.observed_order, 2.0)) - 1) / std::abs(f1);
  else if (m.check == "unconverged")
    m.estimated_relative_error = std::abs(f1 - f2) / std::abs(f1);
  return m;
}

namespace {

/// For each of `fine`'s modes, the index of its coarse counterpart (or -1): the k-th mode
/// of a family (ModeFamily::label: in-plane, out-of-plane, torsion, mixed, rigid; one
/// family on the planar model, where this is pairing by index) with the k-th of the same
/// family on the coarse mesh.
std::vector<int> pairModes(const std::vector<ModeInfo>& fine, const std::vector<ModeInfo>& coarse) {
  std::map<std::string, std::vector<int>> coarse_by_family;
  for (std::size_t j = 0; j < coarse.size(); ++j) coarse_by_family[coarse[j].family.label].push_back(static_cast<int>(j));
  std::map<std::string, std::size_t> taken;
  std::vector<int> match(fine.size(), -1);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const std::string& family = fine[i].family.label;
    const std::vector<int>& same = coarse_by_family[family];
    const std::size_t k = taken[family]++;
    if (k < same.size()) match[i] = same[k];
  }
  return match;
}

/// Each link's peak static stress over the runs (coarsest first), where every run
/// recovered it: assessLadder's Richardson value and order, or "mesh-independent" where
/// the meshes agree to 1e-9 (a link carrying axial load only).
std::vector<StressConvergence> stressConvergence(const ModesReport& finest, const std::vector<std::vector<double>>& runs) {
  std::vector<StressConvergence> out;
  for (std::size_t l = 0; l < finest.static_stress.size(); ++l) {
    std::vector<double> ladder;
    for (const auto& r : runs) ladder.push_back(l < r.size() ? r[l] : NAN);
    if (!std::all_of(ladder.begin(), ladder.end(), [](double v) { return std::isfinite(v) && v > 0; })) continue;
    StressConvergence sc{finest.static_stress[l].peak.link, assessLadder(ModeNumber::atIndex(static_cast<int>(l)), ladder)};
    double spread = 0;
    for (double v : ladder) spread = std::max(spread, std::abs(v - ladder.back()));
    if (spread <= 1e-9 * ladder.back()) {
      sc.ladder.has_estimate = true;
      sc.ladder.has_observed_order = false;
      sc.ladder.extrapolated_hz = ladder.back();
      sc.ladder.estimated_relative_error = 0;  // below 1e-9: round-off, which no machine repeats
      sc.ladder.check = "mesh-independent";
    }
    out.push_back(std::move(sc));
  }
  return out;
}

}  // namespace

DiscretizationEstimate estimateDiscretization(const ArticleScene& scene, const ModesReport& finest) {
  DiscretizationEstimate e;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> finest_hz = reportFrequencies(finest);
  bool flexible = false, by2 = true, by4 = true;
  for (const auto& l : scene.article.links) {
    if (l.rigid) continue;
    flexible = true;
    by2 = by2 && l.segments % 2 == 0;
    by4 = by4 && l.segments % 4 == 0;
  }
  if (!flexible) {
    e.reason = "no flexible link";
    return e;
  }
  if (!by2) {
    e.reason = "a flexible link has an odd number of segments (the estimate halves them)";
    return e;
  }
  e.divisors = by4 ? std::vector<int>{4, 2} : std::vector<int>{2};
  // Each coarse mesh solved for more modes than the finest has: a mode's counterpart may
  // sit further down the list there.
  std::vector<std::vector<double>> runs;
  std::vector<bool> unpaired(finest_hz.size(), false);  ///< the coarse mesh has enough modes, none of this one's family
  std::vector<std::vector<double>> stress_runs;  ///< per run, each link's peak static stress (NaN: not recovered)
  auto peakStresses = [](const ModesReport& r) {
    std::vector<double> out;
    for (const auto& l : r.static_stress) out.push_back(l.peak.recovered ? l.peak.stress.equivalent : NAN);
    return out;
  };
  for (int d : e.divisors) {
    ArticleScene coarse = scene;
    for (auto& l : coarse.article.links)
      if (!l.rigid) l.segments /= d;
    ModesOptions mo;
    mo.max_modes = static_cast<int>(finest_hz.size()) + std::max(4, static_cast<int>(finest_hz.size()) / 2);
    mo.with_shapes = false;
    const ModesReport c = runModes(coarse, mo);
    const std::vector<int> match = pairModes(finest.modes, c.modes);
    std::vector<double> f(finest_hz.size(), NAN);
    for (std::size_t i = 0; i < f.size() && i < match.size(); ++i) {
      if (match[i] >= 0) f[i] = c.modes[static_cast<std::size_t>(match[i])].frequency_hz;
      else if (i < c.modes.size()) unpaired[i] = true;
    }
    runs.push_back(std::move(f));
    stress_runs.push_back(peakStresses(c));
  }
  stress_runs.push_back(peakStresses(finest));
  e.stresses = stressConvergence(finest, stress_runs);
  double scale = 0;
  for (double f : finest_hz) scale = std::max(scale, std::abs(f));
  for (std::size_t i = 0; i < finest_hz.size(); ++i) {
    std::vector<double> f;
    for (const auto& r : runs) f.push_back(r[i]);
    f.push_back(finest_hz[i]);
    ConvergenceMode m = assessLadder(ModeNumber::atIndex(static_cast<int>(i)), f);
    if (!(std::abs(finest_hz[i]) > 1e-6 * scale)) {  // a rigid-body mode: no relative error
      m.has_estimate = m.has_observed_order = false;
      m.check = "rigid";
    } else if (unpaired[i]) {  // no coarse mode of its family: nothing to extrapolate from
      m.has_estimate = m.has_observed_order = false;
      m.check = "unpaired";
    }
    e.modes.push_back(std::move(m));
  }
  e.available = true;
  e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return e;
}

namespace {

/// The worst of the first modes' estimates at the finest of `runs`, each mode followed
/// down the two coarser runs within its family (pairModes).
SegmentsLevel assessLevel(const std::vector<std::vector<ModeInfo>>& runs, int num_modes, double target) {
  SegmentsLevel level;
  level.worst_error = NAN;
  if (runs.size() < 3) return level;
  const std::vector<ModeInfo>& finest = runs.back();
  double scale = 0;
  for (const ModeInfo& m : finest) scale = std::max(scale, std::abs(m.frequency_hz));
  const std::vector<int> pair2 = pairModes(finest, runs[runs.size() - 2]), pair3 = pairModes(finest, runs[runs.size() - 3]);
  auto at = [](const std::vector<ModeInfo>& run, int j) { return j >= 0 ? run[static_cast<std::size_t>(j)].frequency_hz : NAN; };
  level.met = true;
  level.worst_error = 0;
  bool worst_trusted = true;
  for (int i = 0; i < num_modes && i < static_cast<int>(finest.size()); ++i) {
    if (finest[i].rigid_body || !(std::abs(finest[i].frequency_hz) > 1e-6 * scale)) continue;  // a rigid-body mode
    const std::vector<double> f{at(runs[runs.size() - 3], pair3[i]), at(runs[runs.size() - 2], pair2[i]), finest[i].frequency_hz};
    const ConvergenceMode m = assessLadder(ModeNumber::atIndex(i), f);
    const bool trusted = m.check == "ok" || m.check == "order";
    const double e = m.has_estimate ? m.estimated_relative_error : INFINITY;
    if (!trusted || !(e <= target)) level.met = false;
    // The worst mode: an untrusted one before any trusted one, then the largest estimate.
    const bool worse = !level.worst_mode || (!trusted && worst_trusted) ||
                       (trusted == worst_trusted && !(e <= level.worst_error));
    if (worse) {
      level.worst_error = e;
      level.worst_mode = ModeNumber::atIndex(i);
      level.worst_check = m.check.empty() ? "unchecked" : m.check;
      worst_trusted = trusted;
    }
  }
  return level;
}

}  // namespace

SegmentsChoice segmentsForTarget(const ArticleScene& scene, int num_modes, double target, int max_segments,
                                 double budget_s) {
  MMV_DEMAND(target > 0 && target < 1);  // checked by the study (sim/app)
  SegmentsChoice c;
  c.target = target;
  const auto t0 = std::chrono::steady_clock::now();
  auto since = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  std::vector<std::vector<ModeInfo>> runs;
  for (int n = 1; n <= max_segments; n *= 2) {
    ArticleScene s = scene;
    overrideSegments(s, n);
    const double start = since();
    ModesOptions mo;  // more modes than asked for: a mode's counterpart may sit further down a coarser run
    mo.max_modes = num_modes + std::max(4, num_modes / 2);
    mo.with_shapes = false;
    runs.push_back(runModes(s, mo).modes);
    SegmentsLevel level = assessLevel(runs, num_modes, target);
    level.segments = n;
    level.seconds = since() - start;
    c.ladder.push_back(level);
    if (level.met) {
      c.segments = n;
      c.seconds = since();
      return c;
    }
    if (budget_s > 0 && since() > budget_s) break;
  }
  c.seconds = since();
  const SegmentsLevel& last = c.ladder.back();
  const std::string best = std::isfinite(last.worst_error)
                               ? strf("at %d segments per link mode %d is still %.3g %% off (%s)", last.segments,
                                      last.worst_mode.value().number(), 100 * last.worst_error, last.worst_check.c_str())
                               : strf("only %d segments per link were solved", last.segments);
  throw NumericalError(strf("--target-error %g (relative frequency error of the first %d modes) cannot be met ", target,
                            num_modes) +
                       (budget_s > 0 && since() > budget_s ? strf("within the %g s budget", budget_s)
                                                           : strf("with up to %d segments per link", max_segments)) +
                       ": " + best);
}

ConvergenceStudy runConvergence(const ArticleScene& scene, int max_segments, int num_modes) {
  ConvergenceStudy study;
  study.scene_name = scene.name;
  study.scene_source = scene.source;
  for (int n = 1; n <= max_segments; n *= 2) {
    ArticleScene s = scene;
    overrideSegments(s, n);
    const auto t0 = std::chrono::steady_clock::now();
    const ModesSolve sol = solveSceneModes(s, {}, num_modes);
    ConvergenceRun run;
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    run.segments = n;
    run.num_dofs = sol.num_dofs;
    run.frequency_hz.assign(sol.frequencies_hz.data(), sol.frequencies_hz.data() + sol.frequencies_hz.size());
    study.runs.push_back(std::move(run));
  }
  for (int i = 0; i < num_modes; ++i) {
    std::vector<double> f;
    for (const auto& run : study.runs) f.push_back(i < static_cast<int>(run.frequency_hz.size()) ? run.frequency_hz[i] : NAN);
    study.modes.push_back(assessLadder(ModeNumber::atIndex(i), f));
  }
  return study;
}

}  // namespace mmv

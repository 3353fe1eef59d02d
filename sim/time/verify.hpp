#pragma once
/// A time run's error estimate by a companion run (`simulate --verify`): the same run
/// at a 10x tighter tolerance (relative, and absolute where one is set), compared at
/// every sample on the scored points (every link tip and the scene's score_points; the
/// isolator's optical table and spring box). For an integrator of order p the
/// companion's own error is about 10^-p of the run's, so the difference estimates the
/// run's error; it does not see the discretization (segments), which `converge` and
/// `trade`'s segment ladder measure.
///
/// The comparison functions are the ones `trade` scores its runs with.

#include <functional>
#include <string>
#include <vector>

#include "sim/time/simulation.hpp"

namespace mmv {

/// Where two runs' scored points are farthest apart.
struct ScoredDistance {
  double distance_m = 0;
  double at_s = 0;
  std::string point;
};

/// The largest distance between the two runs' scored points (every one when `points`
/// is empty) over their common samples.
ScoredDistance scoredDistance(const SimulationRecord& a, const SimulationRecord& b, const std::vector<std::string>& points);

/// The largest distance of the scored points from their first sample.
double scoredAmplitude(const SimulationRecord& a, const std::vector<std::string>& points);

/// The size of what the scored points span (m): the largest distance between two of
/// them at one sample (the article's extent when its tips are scored). Independent of
/// where the scene puts its origin; 0 for a single point.
double scoredScale(const SimulationRecord& a, const std::vector<std::string>& points);

/// The smallest motion counted as motion: a micrometre per metre of the scored points'
/// extent (`scale_m`). Below it an article held at rest only drifts by integration
/// noise (CPodes at 1e-6 moves the closed article's tips 2 nm in 10 s), and 1 % of that
/// drift is no target.
constexpr double kMotionFloor = 1e-6;

/// The target an error is held to when the user gives none: 1 % of the scored points'
/// largest motion, the motion counted as no less than kMotionFloor x `scale_m`; 1e-4 m
/// if both are 0 (one point scored that does not move).
double defaultErrorTarget(double amplitude_m, double scale_m);

/// Runs `rerun` at the run's tolerances / 10, recording the scored points only
/// (SimulationSpec::scored_only: the same steps, so the same positions as a full
/// record, without its outputs' cost), and fills the estimate. `target_m` <= 0:
/// defaultErrorTarget of the companion's amplitude and scale. Throws what `rerun` throws.
RunVerification verifyRun(const SimulationResult& run, const SimulationSpec& spec,
                          const std::function<SimulationResult(const SimulationSpec&)>& rerun, double target_m);

/// The safety factor a verified run's estimate is held to: "met" means
/// kVerifySafetyFactor x estimate <= target. The estimate is the run's distance from a
/// companion at 10x tighter tolerances, so the companion's own error, and an error that
/// does not fall with the tolerance as the method's order says, are not in it: on a
/// pendulum released from 170 deg (CVODE Adams at 1e-7) the true error was 1.15 to 1.39
/// times the estimate (tests/sim/time/verify_test.cpp measures it). The contract
/// (`--target-error`, sim/time/target.hpp) holds its candidates to the same factor.
inline constexpr double kVerifySafetyFactor = 2.0;

/// The estimate, with its safety factor, within the target.
bool verificationMet(const RunVerification& v);

/// A warning when the estimate, with its safety factor, exceeds its target; empty otherwise.
std::string verificationWarning(const RunVerification& v);

}  // namespace mmv

#pragma once
/// `frf` and `rom` on the article: the linear model between named inputs and outputs
/// (sim/linear), its modal reduction, the responses of both on a grid that resolves
/// every kept mode's half-power band, the reduced model's error against the full one,
/// and the mesh's share of the FRF error. (The isolator's frf and rom: sim/cli for now.)

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/linear/test_geometry.hpp"
#include "sim/modes/converge.hpp"

namespace mmv::app {

struct LinearRequest {
  std::vector<std::string> inputs;   ///< table_x, torque:JOINT, force:POINT:x, ...; empty: table_x, table_y.
  std::vector<std::string> outputs;  ///< POINT:AXIS[:disp|vel|acc|acc_abs]; empty: every link tip.
  double f_min = 0.01, f_max = 100;  ///< Hz, 0 < f_min < f_max.
  bool range_given = false;          ///< f_min or f_max given: the grid is theirs even with a band.
  int points = 400;                  ///< log-spaced frequencies, 2 .. 100000.
  int rom_modes = 8;                 ///< modes kept, 1 .. 10000.
  std::optional<std::pair<double, double>> band;  ///< keep the modes in [min, max] Hz instead.
  bool residualize = true;
  double damping_ratio = 0.01;  ///< every mode's, 0 .. 1; used when given or the scene has none.
  bool damping_given = false;
  double rom_target = 0.01;   ///< the reduced model's error the modes-needed count is for (0: not computed); 0 .. 1.
  double target_error = 0;    ///< > 0 (<= 0.5): segments and kept modes chosen for it.
  double time_budget = 0;     ///< s; > 0: the target's choice of segments within it.
  bool segments_given = false;
  std::string vary;           ///< HAM-SAS frf only: one parameter over values, "KEY=V1,V2,...".
  Front front = Front::Cli;
};

/// Checks every option (UsageError naming it) and returns the response grid, Hz: the
/// range, or the band when one is given without a range.
std::vector<double> checkLinearRequest(const LinearRequest& request);
/// The reduction the request asks for.
ReductionOptions reductionOptions(const LinearRequest& request);
/// The same for the article's model `lm`: with its proportional modes, if any.
ReductionOptions reductionOptions(const LinearRequest& request, const LinearModel& lm);

struct LinearStudy {
  ArticleScene scene;  ///< at the segments used
  LinearModel lm;
  ReducedModel red;
  std::vector<double> f, w;            ///< the grid, Hz and rad/s
  std::vector<Eigen::MatrixXcd> hf;    ///< the full model's responses on it
  ModelError err;                      ///< the reduced model's against them
  std::optional<SegmentsChoice> segments;  ///< target_error: how the segments were chosen
  /// target_error: E (of each pair's peak), the frequency error the segments hold every
  /// mode up to f_max to for the mesh's half of it, and the least damping ratio that
  /// set it (chooseForTarget, linear_study.cpp).
  double frf_target = 0, frequency_target = 0, least_damping = 0;
  /// The mesh's share of the FRF error near the peaks, which `err` (reduced against full
  /// on this mesh) does not see: near its peak a mode whose frequency is off by e
  /// (relative) moves the response by about |e / (e + i zeta)| ~ e / zeta of the peak.
  /// The worst over the vibration modes up to f_max (capped at 1); -1: not estimated.
  double mesh_error = -1;
  std::optional<ModeNumber> mesh_mode;  ///< the mode of the worst term; none: not estimated
  double mesh_mode_hz = 0, mesh_mode_error = 0, mesh_mode_zeta = 0;
  std::string mesh_note;  ///< why not estimated
  TestGeometry geometry;  ///< nodes, trace lines and the first kLinearModelModes shapes (frf.uff)

  std::string summaryText() const;                ///< frf's and rom's text report
  nlohmann::ordered_json frfJson() const;         ///< `frf --json`
  nlohmann::ordered_json romJson() const;         ///< rom.json, `rom --json`
};

LinearStudy runLinearStudy(const ArticleScene& scene, const LinearRequest& request);

}  // namespace mmv::app

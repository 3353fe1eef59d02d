#pragma once
/// `update` as a study: the scene's uncertain values adjusted so that its model
/// reproduces a measured modal test (sim/linear/model_update.hpp, docs/updating.md).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/correlate_study.hpp"
#include "sim/app/study.hpp"
#include "sim/linear/model_update.hpp"

namespace mmv::app {

/// At most this many parameters in one update.
inline constexpr int kMaxUpdateParameters = 12;

struct UpdateRequest {
  /// KEY or KEY:LO:HI: a number written in the scene file, named as --set names it;
  /// bounds in its units (default: half to twice the nominal), holding the nominal.
  std::vector<std::string> params;
  CorrelateRequest pairing;       ///< the measured file and how its modes pair (its tam unused).
  double frequency_sigma = 0.01;  ///< 1e-6 .. 1: relative; a frequency error's weight is 1 / it.
  double mac_sigma = 0.05;        ///< 1e-6 .. 1: (1 - MAC)'s weight is 1 / it.
  bool mac_residuals = true;      ///< (1 - MAC) among the residuals.
  double regularization = 0;      ///< 0 .. 1e6: pull toward the nominal, residuals per 100 % change.
  int max_iterations = 30;        ///< 1 .. 1000.
};

struct UpdateStudy {
  ModelUpdateResult result;
  nlohmann::ordered_json json;
  std::string text, parameters_csv, pairs_csv, iterations_csv;
};

/// Checks the request (every option and parameter, their bounds through the scene
/// reader, before the measured file is read; the file before any model is built), then
/// updates: an article against the measured file's modes, HAM-SAS against the slides'
/// measured features (no file; (1 - MAC) is not a residual there: the features' shapes
/// are model patterns, not measurements).
UpdateStudy runUpdateStudy(const LoadedScene& scene, const UpdateRequest& request);
/// The same for an article on a measured set already read (tests add noise to one).
UpdateStudy runUpdateStudy(const LoadedScene& scene, const UpdateRequest& request, const MeasuredSet& measured);

}  // namespace mmv::app

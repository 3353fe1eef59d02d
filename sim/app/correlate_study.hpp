#pragma once
/// `correlate` as a study: a measured modal test (UFF 15/2411 nodes, 55 mode shapes, 58
/// functions) against an article scene's model (sim/linear/correlation.hpp).

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/linear/test_orthogonality.hpp"

#include "sim/app/study.hpp"
#include "sim/linear/correlation.hpp"

namespace mmv::app {

struct CorrelateRequest {
  std::string measured;             ///< the measured UFF file (required).
  double pair_distance_m = 0.05;    ///< 1e-6 .. 100 m: a node farther from the article is not paired.
  std::vector<std::string> pairs;   ///< NODE=POINT (a node label of the file, a point or station of the scene).
  int modes = 20;                   ///< model modes compared, 1 .. 500.
  double mac_threshold = 0.7;       ///< 0 .. 1.
  double max_frequency_error = 0.3; ///< 1e-6 .. 100: |f_model / f_test - 1| above it is not a pair.
  std::optional<double> damping_ratio;  ///< 0 .. 1 for every mode; empty: the scene's damping, else 0.01.
  /// FILE[:METHOD]: a TAM from `place-sensors --tam --out` (tam.mat) for the measured
  /// modes' test orthogonality; METHOD (guyan, irs, serep) when the file holds several.
  std::string tam;
  Front front = Front::Cli;
};

struct CorrelateStudy {
  CorrelationResult result;
  std::optional<TestOrthogonality> test_orthogonality;  ///< with a TAM
  nlohmann::ordered_json json;
  std::string text, mac_csv, pairs_csv;
};

/// The measured UFF file, read and bounded (SceneFileError, SceneError naming file:line).
MeasuredSet readMeasuredFile(const std::string& path);
/// The request's pairing options, checked (UsageError naming the option as `front` spells it).
CorrelateOptions correlateOptions(const CorrelateRequest& request, const ArticleScene& scene);
/// Every node a --pair names is one of the file's (SceneError otherwise).
void checkNamedPairNodes(const MeasuredSet& test, const CorrelateOptions& options, Front front);

/// Checks the request (every option before the file is read, the file before any model
/// is built), reads the measured file and correlates it with the article of `scene`
/// (a HAM-SAS scene is a UsageError).
CorrelateStudy runCorrelateStudy(const Scene& scene, const CorrelateRequest& request);

}  // namespace mmv::app

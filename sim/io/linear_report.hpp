#pragma once
/// Writers for the article's linear models (sim/linear/): the summary table of every
/// input-output pair, the FRF CSV per pair, the UFF file (nodes, trace lines, modes,
/// FRFs), and rom.json (docs/outputs.md).

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "sim/linear/state_space.hpp"
#include "sim/linear/test_geometry.hpp"

namespace mmv {

/// `s` with every character other than letters, digits, '.', '_' and '-' replaced by '_'.
std::string safeFileName(std::string s);
/// `hf`: the full model's responses at f (fullResponses), reused for the peaks.
/// One line: the largest local FRF error of a reduced model, where and for which pair
/// (empty without pairs); and the same in JSON (max_local_relative_frf_error,
/// max_local_error_hz, max_local_error_pair).
std::string localErrorLine(const ModelError& err, const std::vector<std::string>& outputs,
                           const std::vector<std::string>& inputs);
void addLocalError(nlohmann::ordered_json& j, const ModelError& err, const std::vector<std::string>& outputs,
                   const std::vector<std::string>& inputs);

std::string linearSummaryText(const LinearModel& lm, const ReducedModel& red, const ModelError& err,
                              const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& hf);
/// The same summary as JSON (docs/outputs.md, frf --json).
nlohmann::ordered_json linearSummaryJson(const LinearModel& lm, const ReducedModel& red, const ModelError& err,
                                         const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& hf,
                                         const std::string& scene_name);
/// The UFF file: the test geometry `g` (sim/linear/test_geometry.hpp: nodes at the
/// equilibrium's named points and the base, a trace line per link, the first mode shapes
/// with their damping ratios under the model's damping), and every FRF (or
/// transmissibility) pair of `h` at f (Hz), each referred to a node the file defines.
std::string frfUff(const LinearModel& lm, const TestGeometry& g, const ArticleScene& scene, const std::vector<double>& f,
                   const std::vector<Eigen::MatrixXcd>& h);
/// frf_<output>__<input>.csv: magnitude (dB and in units), phase, and the reduced model's.
std::string frfCsv(const StateSpace& s, Eigen::Index o, Eigen::Index i, const std::vector<double>& f,
                   const std::vector<Eigen::MatrixXcd>& full, const std::vector<Eigen::MatrixXcd>& reduced);
nlohmann::ordered_json romJson(const LinearModel& lm, const ReducedModel& red, const ModelError& err,
                               const std::vector<double>& f);

}  // namespace mmv

#pragma once
/// Writers for the HAM-SAS isolator (sim/hamsas/): the modes with the measured-vs-model
/// table, the ground-to-table transmissibility and its parameter variation, the
/// actuator-to-sensor control model (docs/outputs.md, "HAM-SAS scenes").

#include <nlohmann/json.hpp>

#include <complex>
#include <string>
#include <vector>

#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/fields.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// 20 log10 |v| (dB), with a floor far below any physical value for an exact zero.
double decibels(std::complex<double> v);
/// "x", "y", "z", "rx", "ry", "rz" for k = 0..5.
const char* hamsasDofName(int k);
/// One line: bodies, coordinates, how the effective joints are modelled.
std::string hamsasDescription(const HamsasModes& h);
std::string hamsasModesText(const HamsasScene& scene, const HamsasModes& h, int max_modes);
nlohmann::ordered_json hamsasModesJson(const HamsasScene& scene, const HamsasModes& h, int max_modes);
/// A mode of the isolator as the reports show it; the first `max_modes` (0: all).
struct HamsasModeRow {
  const HamsasModes* h = nullptr;
  int i = 0;  ///< 0-based
};
std::vector<HamsasModeRow> hamsasModeRows(const HamsasModes& h, int max_modes);
/// Its fields: modes.json's mode records, modes.csv's columns (the scalar ones) and the
/// text table's values.
const std::vector<Field<HamsasModeRow>>& hamsasModeFields();
std::string hamsasModesCsv(const HamsasModes& h, int max_modes);
/// The 6 x 6 transmissibility's diagonal (peaks, 10 Hz against the 70-80 dB goal) and
/// the largest cross-coupling at 10 Hz; T at the frequencies f (Hz), T10 at 10 Hz.
std::string hamsasTransmissibilityText(const HamsasScene& scene, const HamsasModes& h, const std::vector<double>& f,
                                       const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10);
std::string hamsasVaryText(const std::string& key, const std::vector<HamsasVaryPoint>& points);
/// transmissibility.csv: frequency, then dB and phase of every pair.
/// frf --json on an isolator: the 6 x 6 transmissibility at 10 Hz (dB of m/m, m/rad,
/// rad/m, rad/rad) and every pair's curve (dB, deg) over the frequencies.
nlohmann::ordered_json hamsasTransmissibilityJson(const HamsasScene& scene, const std::vector<double>& f,
                                                  const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10);
std::string hamsasTransmissibilityCsv(const std::vector<double>& f, const std::vector<Eigen::MatrixXcd>& T);
nlohmann::ordered_json hamsasRomJson(const StateSpace& full, const ReducedModel& red, const ModelError& err,
                                     const std::vector<double>& f);
std::string hamsasRomText(const HamsasScene& scene, const HamsasModes& h, const StateSpace& full, const ReducedModel& red,
                          const ModelError& err, const std::vector<double>& f);

}  // namespace mmv

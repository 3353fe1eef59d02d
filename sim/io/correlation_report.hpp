#pragma once
/// Writers for `mmvlab correlate` (sim/linear/correlation.hpp): the measured set from a
/// UFF file, the text report, JSON (docs/correlation.md) and the MAC matrix as CSV.

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "sim/io/fields.hpp"
#include "sim/io/uff.hpp"
#include "sim/linear/correlation.hpp"
#include "sim/linear/test_orthogonality.hpp"

namespace mmv {

/// The nodes, modes and functions of a read UFF file (sim/io/uff_read.hpp), as the
/// correlation takes them.
MeasuredSet measuredSet(const uff::File& file, const std::string& source);

/// A model mode's label with its frequency, "M3 4.12 Hz"; a test mode's, "T3 4.12 Hz".
std::string modeLabel(char prefix, int number, double frequency_hz);

std::string correlationText(const ArticleScene& scene, const CorrelationResult& r);
nlohmann::ordered_json correlationJson(const ArticleScene& scene, const CorrelationResult& r);
/// mac.csv, one row per test-model mode pair: test_mode, test_frequency_hz, model_mode,
/// model_frequency_hz, mac (long form: read as it is by numpy, pandas, Octave).
std::string macCsv(const CorrelationResult& r);

/// A paired test and model mode, as the reports show it.
struct CorrelationPairRow {
  std::string test, model;  ///< "T3", "M4"
  double test_hz = 0, model_hz = 0, mac = 0;
  double test_damping_ratio = 0;
  std::optional<double> model_damping_ratio;  ///< none when the model is undamped
};
std::vector<CorrelationPairRow> correlationPairRows(const CorrelationResult& r);
/// The fields of a pair: correlation.json's pairs, pairs.csv's columns, the text table's
/// values and Python's CorrelateResult.table().
const std::vector<Field<CorrelationPairRow>>& correlationPairFields();
/// pairs.csv: a row per pair, a column per field.
std::string correlationPairsCsv(const CorrelationResult& r);

/// correlation.json's "test_orthogonality" (`correlate --tam`): {tam, method, channels,
/// criterion_off_diagonal_max, pass, modes: [{test_mode, frequency_hz,
/// max_off_diagonal, pass}], matrix (normalised), left_out}; and its text section.
nlohmann::ordered_json testOrthogonalityJson(const TestOrthogonality& t);
std::string testOrthogonalityText(const TestOrthogonality& t);

}  // namespace mmv

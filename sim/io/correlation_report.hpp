#pragma once
/// Writers for `mmvlab correlate` (sim/linear/correlation.hpp): the measured set from a
/// UFF file, the text report, JSON (docs/correlation.md) and the MAC matrix as CSV.

#include <nlohmann/json.hpp>

#include <string>

#include "sim/io/uff.hpp"
#include "sim/linear/correlation.hpp"

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

}  // namespace mmv

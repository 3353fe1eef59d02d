#pragma once
// The last line of defence of "no NaN reaches an output": where in a finished report a
// non-finite number would be printed. Commands check every result with it before
// printing or committing (sim/cli/commands.hpp, emitResult); the fuzz targets judge
// with it too (tests/fuzz/fuzz_targets.cpp).
#include <string>

#include <nlohmann/json.hpp>

namespace mmv {

/// "line N: 'the line'" of the first line printing a NaN or an inf (as a word: "nan",
/// "-inf", "NaN"; "infinite" is a word, not a number), or "" when there is none.
std::string firstNonFiniteLine(const std::string& text);

/// The JSON pointer ("/modes/3/frequency_hz") of the first non-finite number, or "".
/// (nlohmann's dump would print it as null, so the text of a JSON cannot tell.)
std::string firstNonFiniteJson(const nlohmann::ordered_json& json);

}  // namespace mmv

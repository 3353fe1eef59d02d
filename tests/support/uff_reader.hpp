#pragma once
/// Test support: a reader for the UFF datasets sim/io/uff.hpp writes (151, 164, 15,
/// 82, 55, 58), used by the round-trip and fixed-width layout tests.

#include <string>

#include "sim/io/uff.hpp"

namespace mmv::uff {

/// Parses the datasets above (others are skipped); throws std::runtime_error naming
/// the line of a malformed record.
File read(const std::string& text);

}  // namespace mmv::uff

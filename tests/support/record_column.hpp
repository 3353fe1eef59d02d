#pragma once
// Test support: a time run's column by name (a failure, and column 0, when it has none).

#include <gtest/gtest.h>

#include <string>

#include "sim/time/simulation.hpp"

namespace mmv::testing {

inline int column(const SimulationRecord& r, const std::string& name) {
  for (std::size_t c = 0; c < r.columns.size(); ++c)
    if (r.columns[c] == name) return static_cast<int>(c);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

}  // namespace mmv::testing

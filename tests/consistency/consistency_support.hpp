#pragma once
// What the consistency tests share (tests/consistency/): the shipped scenes, a JSON
// document less its wall times, a text line's words, and the fixture.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli.hpp"

namespace mmv::consistency_testing {

using cli_testing::Cli;
using json = nlohmann::json;
namespace fs = std::filesystem;

inline std::vector<std::string> shippedScenes() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(MMVLAB_SOURCE_DIR) / "scenes"))
    if (e.path().extension() == ".yaml") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

/// `j` without the fields that measure wall time (they differ between two runs).
inline json withoutTimes(json j) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end();) {
      const std::string& k = it.key();
      if (k == "time_s" || k == "seconds" || k.find("wall_time") != std::string::npos) it = j.erase(it);
      else *it = withoutTimes(*it), ++it;
    }
  } else if (j.is_array()) {
    for (auto& x : j) x = withoutTimes(x);
  }
  return j;
}

class Consistency : public Cli {};

/// The whitespace-separated words of `line`.
inline std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> w;
  std::stringstream ss(line);
  for (std::string x; ss >> x;) w.push_back(x);
  return w;
}

}  // namespace mmv::consistency_testing

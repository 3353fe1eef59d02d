#pragma once
/// Writing a command's files into --out DIR without half-written results: every file
/// is first written into a private staging directory next to DIR; commit() then
/// checks that no file would replace one the user already has (unless --force) and
/// moves them all into DIR. If anything fails before commit(), DIR is untouched and
/// the staging directory is removed.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/core/errors.hpp"

namespace mmv {

class OutputDir {
 public:
  OutputDir(const std::string& dir, bool force);
  OutputDir(const OutputDir&) = delete;
  OutputDir& operator=(const OutputDir&) = delete;
  ~OutputDir();

  /// Where to write `name` now (inside the staging directory).
  std::string stage(const std::string& name);
  /// Moves every staged file into the target directory; returns their final paths.
  std::vector<std::string> commit();

 private:
  std::filesystem::path target_, staging_;
  std::vector<std::string> names_;
  bool force_ = false, committed_ = false;
};

}  // namespace mmv

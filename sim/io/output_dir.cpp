#include "sim/io/output_dir.hpp"

#include <unistd.h>

#include <algorithm>

namespace mmv {

namespace fs = std::filesystem;

OutputDir::OutputDir(const std::string& dir, bool force) : target_(dir), force_(force) {
  std::error_code ec;
  if (fs::exists(target_, ec) && !fs::is_directory(target_, ec))
    throw OutputError(dir + ": exists and is not a directory");
  fs::path parent = fs::absolute(target_, ec).parent_path();
  fs::create_directories(parent, ec);  // like mkdir -p; empty directories only
  if (!fs::is_directory(parent, ec)) throw OutputError(dir + ": cannot create its parent directory " + parent.string());
  staging_ = parent / (".mmvlab-staging-" + std::to_string(::getpid()) + "-" + target_.filename().string());
  fs::remove_all(staging_, ec);
  if (!fs::create_directory(staging_, ec)) throw OutputError(dir + ": cannot create files next to it: " + ec.message());
}

OutputDir::~OutputDir() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::string OutputDir::stage(const std::string& name) {
  names_.push_back(name);
  return (staging_ / name).string();
}

std::vector<std::string> OutputDir::commit() {
  std::error_code ec;
  if (!force_) {
    for (const auto& n : names_)
      if (fs::exists(target_ / n, ec))
        throw OutputError((target_ / n).string() + " exists: nothing was written (use --force to replace)");
  }
  fs::create_directories(target_, ec);
  if (ec) throw OutputError(target_.string() + ": cannot create directory: " + ec.message());
  std::vector<std::string> out;
  for (const auto& n : names_) {
    fs::rename(staging_ / n, target_ / n, ec);
    if (ec) throw OutputError((target_ / n).string() + ": cannot write: " + ec.message());
    out.push_back((target_ / n).string());
  }
  committed_ = true;
  return out;
}

}  // namespace mmv

#include "sim/core/plugins.hpp"

#include <limits.h>
#include <unistd.h>

#include <filesystem>

namespace mmv {

std::vector<std::string> pluginCandidates(const std::string& file, const std::string& built_path) {
  std::vector<std::string> candidates;
  char exe[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = '\0';
    candidates.push_back((std::filesystem::path(exe).parent_path() / file).string());
  }
  if (!built_path.empty()) candidates.push_back(built_path);
  return candidates;
}

}  // namespace mmv

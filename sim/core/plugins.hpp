#pragma once
/// Where mmvlab's plugins (the SUNDIALS steppers, the figures) are looked for: next to
/// the running executable first, then where the build put them.

#include <string>
#include <vector>

namespace mmv {

/// `file` beside /proc/self/exe, then `built_path` (when not empty).
std::vector<std::string> pluginCandidates(const std::string& file, const std::string& built_path);

}  // namespace mmv

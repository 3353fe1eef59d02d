#pragma once
/// Where mmvlab's plugins (the SUNDIALS steppers, the figures) are looked for: next to
/// the running executable first, then where the build put them.

#include <functional>
#include <string>
#include <vector>

namespace mmv {

/// `file` beside /proc/self/exe, then `built_path` (when not empty).
std::vector<std::string> pluginCandidates(const std::string& file, const std::string& built_path);

/// The table of the first of pluginCandidates(file, built_path) that loads, exports
/// `symbol` (a function returning its table) and whose table `accept` takes (its
/// version); kept loaded for the process's life. nullptr, with `failure` naming every
/// path tried and why ("not this version's <what>"), when none does.
const void* loadPluginTable(const std::string& file, const std::string& built_path, const char* symbol,
                            const std::function<bool(const void*)>& accept, const std::string& what, std::string& failure);

}  // namespace mmv

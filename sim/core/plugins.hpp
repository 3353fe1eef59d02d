#pragma once
/// Where mmvlab's plugins (the SUNDIALS steppers, the figures, the .mat reader, the
/// video writer) are looked for: beside the object this code is linked into (the
/// executable, or the Python module's _mmvlab*.so in its package), beside the running
/// executable, in the installed layout's PREFIX/lib/mmvlab/ (the executable in
/// PREFIX/bin, `cmake --install`), then where the build put them.

#include <functional>
#include <string>
#include <vector>

namespace mmv {

/// `file` in those places, in that order, each once (`built_path` last, when not empty).
std::vector<std::string> pluginCandidates(const std::string& file, const std::string& built_path);

/// The table of the first of pluginCandidates(file, built_path) that loads, exports
/// `symbol` (a function returning its table) and whose table `accept` takes (its
/// version); kept loaded for the process's life. nullptr, with `failure` naming every
/// path tried and why ("not this version's <what>"), when none does.
const void* loadPluginTable(const std::string& file, const std::string& built_path, const char* symbol,
                            const std::function<bool(const void*)>& accept, const std::string& what, std::string& failure);

}  // namespace mmv

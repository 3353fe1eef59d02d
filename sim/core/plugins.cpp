#include "sim/core/plugins.hpp"

#include <dlfcn.h>
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
  // The build's own path is often the one beside the executable: tried (and named) once.
  if (!built_path.empty() && (candidates.empty() || std::filesystem::path(built_path).lexically_normal() !=
                                                         std::filesystem::path(candidates[0]).lexically_normal()))
    candidates.push_back(built_path);
  return candidates;
}

const void* loadPluginTable(const std::string& file, const std::string& built_path, const char* symbol,
                            const std::function<bool(const void*)>& accept, const std::string& what, std::string& failure) {
  for (const auto& path : pluginCandidates(file, built_path)) {
    // Not RTLD_DEEPBIND: a plugin would then bind libstdc++'s own std::cerr rather than
    // the executable's (copy-relocated, initialised) one and crash on its first message;
    // its copies of mmvlab's code are local symbols (--exclude-libs, hidden visibility)
    // and bind to themselves.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      failure += (failure.empty() ? "" : "; ") + path + " (" + ::dlerror() + ")";
      continue;
    }
    using Get = const void* (*)();
    const auto get = reinterpret_cast<Get>(::dlsym(handle, symbol));
    const void* table = get ? get() : nullptr;
    if (!table || !accept(table)) {
      failure += (failure.empty() ? "" : "; ") + path + " (not this version's " + what + ")";
      continue;
    }
    return table;
  }
  return nullptr;
}

}  // namespace mmv

#include "sim/core/plugins.hpp"

#include <dlfcn.h>
#include <limits.h>
#include <unistd.h>

#include <filesystem>

namespace mmv {

std::vector<std::string> pluginCandidates(const std::string& file, const std::string& built_path) {
  namespace fs = std::filesystem;
  std::vector<std::string> candidates;
  const auto add = [&](const fs::path& p) {
    const std::string s = p.lexically_normal().string();
    for (const auto& c : candidates)
      if (c == s) return;
    candidates.push_back(s);
  };
  // The shared object (or executable) holding this function: the Python module finds the
  // plugins installed beside it in its package.
  Dl_info info{};
  if (::dladdr(reinterpret_cast<const void*>(&pluginCandidates), &info) != 0 && info.dli_fname && info.dli_fname[0] == '/')
    add(fs::path(info.dli_fname).parent_path() / file);
  char exe[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n > 0) {
    exe[n] = '\0';
    const fs::path dir = fs::path(exe).parent_path();
    add(dir / file);
    add(dir.parent_path() / "lib" / "mmvlab" / file);
  }
  if (!built_path.empty()) add(built_path);
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

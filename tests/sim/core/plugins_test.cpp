// Where plugins are looked for (sim/core/plugins.hpp): beside the executable (which here
// is also the object holding the code), in the installed layout's PREFIX/lib/mmvlab/,
// then where the build put them, each path tried and named once.
#include "sim/core/plugins.hpp"

#include <gtest/gtest.h>
#include <limits.h>
#include <unistd.h>

#include <filesystem>

namespace mmv {
namespace {

namespace fs = std::filesystem;

fs::path besideExe(const std::string& file) {
  char exe[PATH_MAX];
  const ssize_t n = ::readlink("/proc/self/exe", exe, sizeof exe - 1);
  exe[n > 0 ? n : 0] = '\0';
  return fs::path(exe).parent_path() / file;
}
fs::path installed(const std::string& file) {
  return (besideExe(file).parent_path().parent_path() / "lib" / "mmvlab" / file).lexically_normal();
}

TEST(Plugins, TheBuildsPathBesideTheExecutableIsTriedOnce) {
  const fs::path here = besideExe("libnone_of_ours.so");
  const std::string lib = installed("libnone_of_ours.so").string();
  EXPECT_EQ(pluginCandidates("libnone_of_ours.so", here.string()), (std::vector<std::string>{here.string(), lib}));
  // The same file written another way ("dir/./lib.so") is still one candidate.
  const std::string dotted = (here.parent_path() / "." / here.filename()).string();
  EXPECT_EQ(pluginCandidates("libnone_of_ours.so", dotted).size(), 2u);
  EXPECT_EQ(pluginCandidates("libnone_of_ours.so", "/elsewhere/libnone_of_ours.so"),
            (std::vector<std::string>{here.string(), lib, "/elsewhere/libnone_of_ours.so"}));
  EXPECT_EQ(pluginCandidates("libnone_of_ours.so", "").size(), 2u);
}

TEST(Plugins, AMissingPluginNamesEachPathTriedOnce) {
  const fs::path here = besideExe("libnone_of_ours.so");
  std::string failure;
  const void* t = loadPluginTable("libnone_of_ours.so", here.string(), "none", [](const void*) { return true; }, "test plugin",
                                  failure);
  EXPECT_EQ(t, nullptr);
  std::size_t count = 0;
  for (std::size_t at = failure.find(here.string()); at != std::string::npos; at = failure.find(here.string(), at + 1)) ++count;
  EXPECT_EQ(count, 2u) << failure;  // the path, and dlerror()'s message that repeats it
  EXPECT_NE(failure.find(installed("libnone_of_ours.so").string()), std::string::npos) << failure;
  EXPECT_EQ(failure.find("; "), failure.rfind("; ")) << failure;  // two attempts
}

}  // namespace
}  // namespace mmv

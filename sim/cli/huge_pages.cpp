#include "sim/cli/huge_pages.hpp"

#include <malloc.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace mmv::cli {

void reexecWithHugePages(char** argv) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  (void)argv;
  return;  // the sanitizers' allocators replace glibc's malloc: its tunable means nothing there
#else
  if (std::getenv("MMVLAB_NO_HUGE_PAGES")) return;
  const char* old = std::getenv("GLIBC_TUNABLES");
  const std::string tunables = old ? std::string(old) : std::string();
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  const std::string set = tunables.empty() ? "glibc.malloc.hugetlb=1" : tunables + ":glibc.malloc.hugetlb=1";
  if (setenv("GLIBC_TUNABLES", set.c_str(), 1) != 0) return;
  std::fflush(nullptr);
  execv("/proc/self/exe", argv);
  // Not executed: go on as we are, on small pages, without leaving the tunable for children.
  if (old) setenv("GLIBC_TUNABLES", old, 1);
  else unsetenv("GLIBC_TUNABLES");
#endif
}

void keepFreedMemory() {
  mallopt(M_MMAP_THRESHOLD, 256 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

}  // namespace mmv::cli

#include "sim/cli/huge_pages.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>

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
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  if (std::getenv("MMVLAB_NO_HUGE_PAGES")) return;
  if (const char* t = std::getenv("GLIBC_TUNABLES"); t && std::string(t).find("glibc.malloc.hugetlb") != std::string::npos) return;
  // 128 MB of address space (not of memory: nothing is touched) from the heap, below the
  // 256 MB mapping threshold; freed at once, it stays the heap's top (no trim below 1 GB).
  constexpr std::size_t kReserve = std::size_t{128} << 20, kHuge = std::size_t{2} << 20;
  void* p = std::malloc(kReserve);
  if (!p) return;
  const auto lo = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto hi = (reinterpret_cast<std::uintptr_t>(p) + kReserve) & ~(kHuge - 1);
  if (hi > lo) madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
  std::free(p);
#endif
}

}  // namespace mmv::cli

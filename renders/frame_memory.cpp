// The memory a frame needs, checked before OSMesa allocates it (renders/frame.hpp).
#include <cstdio>
#include <stdexcept>

#include "renders/frame.hpp"

namespace mmv::render {
namespace {

/// What the kernel says can be allocated without swapping (MemAvailable), in bytes; -1
/// when it does not say.
double availableMemory() {
  std::FILE* f = std::fopen("/proc/meminfo", "r");
  if (!f) return -1;
  char line[256];
  double kb = -1;
  while (std::fgets(line, sizeof line, f))
    if (std::sscanf(line, "MemAvailable: %lf kB", &kb) == 1) break;
  std::fclose(f);
  return kb < 0 ? -1 : kb * 1024;
}

}  // namespace

/// Refuses a frame whose buffers would not fit in the memory available. OSMesa's
/// colour buffer (4 bytes a sample), its depth and the rasterizer's tiles (measured:
/// 2.1 GB for 12288 x 12288 samples, 14 bytes a sample), and the frame itself (11 bytes
/// a pixel through the reduction and the flips).
void checkFrameMemory(int w, int h, int width, int height) {
  const double need = 14.0 * w * h + 11.0 * width * height, have = availableMemory();
  if (have > 0 && need > have) {
    char msg[256];
    std::snprintf(msg, sizeof msg,
                  "a %d x %d frame (drawn at %d x %d samples) needs about %.2g GB and the machine has %.2g GB available: use a smaller --size",
                  width, height, w, h, need / 1e9, have / 1e9);
    throw std::runtime_error(msg);
  }
}

}  // namespace mmv::render

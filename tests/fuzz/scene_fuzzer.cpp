// libFuzzer entry point: one target per binary, chosen at compile time
// (MMV_FUZZ_TARGET = readerTarget or modesTarget). A breach of the contract aborts, so
// libFuzzer records the input as a crash (tests/fuzz/README.md).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64 * 1024) return -1;  // the shipped scenes are under 8 kB; keep the corpus small
  const auto breach = mmv::fuzz::MMV_FUZZ_TARGET(std::string(reinterpret_cast<const char*>(data), size));
  if (breach) {
    std::fprintf(stderr, "mmvlab contract breach: %s\n", breach->c_str());
    std::abort();
  }
  return 0;
}

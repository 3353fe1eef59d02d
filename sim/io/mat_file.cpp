#include "sim/io/mat_file.hpp"

#include <cstdint>
#include <filesystem>
#include <mutex>

#include "sim/core/errors.hpp"
#include "sim/core/plugins.hpp"

namespace mmv {
namespace {

/// The plugin's table, loaded once per process and kept.
const MatApi& api() {
  static const MatApi* table = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
#ifdef MMVLAB_MAT_PLUGIN
    const std::string built = MMVLAB_MAT_PLUGIN;
#else
    const std::string built;
#endif
    table = static_cast<const MatApi*>(loadPluginTable(
        "libmmvlab_mat.so", built, "mmvlab_mat_api",
        [](const void* t) { return static_cast<const MatApi*>(t)->version == kMatApiVersion; }, ".mat plugin", failure));
  });
  if (!table) throw UnavailableError(".mat files need libmmvlab_mat.so (matio): tried " + failure);
  return *table;
}

}  // namespace

void writeMat(const std::string& path, const MatContents& c) {
  const MatStatus s = api().write(path, c);
  if (s.kind != 0) throw OutputError(s.message);
}

MatContents readMat(const std::string& path, long max_bytes) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneFileError(path + ": no such file (or not a regular file)");
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size > static_cast<std::uintmax_t>(max_bytes))
    throw SceneFileError(path + ": larger than " + std::to_string(max_bytes) + " bytes, more than a .mat file mmvlab reads here");
  MatContents c;
  const MatStatus s = api().read(path, c);
  if (s.kind == 2) throw SceneFileError(s.message);
  if (s.kind == 3) throw SceneError(s.message);
  MMV_DEMAND(s.kind == 0);
  return c;
}

void writeStateSpaceMat(const std::string& path, const StateSpace& d) {
  const StateSpace s = d.standardForm();
  writeMat(path, {{{"A", s.A}, {"B", s.B}, {"C", s.C}, {"D", s.D}, {"E", s.E}, {"Ad", d.A}, {"Bd", d.B}, {"Ed", d.E}},
                  {{"InputName", d.input_names},
                   {"OutputName", d.output_names},
                   {"StateName", d.state_names},
                   {"InputUnit", d.input_units},
                   {"OutputUnit", d.output_units}}});
}

}  // namespace mmv

#include "sim/io/mat_file.hpp"

#include <cstdint>
#include <filesystem>
#include <mutex>

#include <tbb/parallel_invoke.h>

#include "sim/core/errors.hpp"
#include "sim/core/files.hpp"
#include "sim/core/plugins.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/mat5_writer.hpp"

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
  std::string headers;
  writeFileChecked(path, mat5Pieces(c, headers));
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

namespace {

/// `s` is d's standard form (moved in, not copied: the full model's matrices are 2 MB
/// each at 64 segments a link).
void writeForms(const std::string& path, StateSpace s, const StateSpace& d) {
  MatContents c;
  c.matrices.reserve(8);
  const std::pair<const char*, Eigen::MatrixXd*> standard[] = {{"A", &s.A}, {"B", &s.B}, {"C", &s.C}, {"D", &s.D}, {"E", &s.E}};
  for (const auto& [name, m] : standard) c.matrices.emplace_back(name, std::move(*m));
  c.matrices.emplace_back("Ad", d.A);
  c.matrices.emplace_back("Bd", d.B);
  c.matrices.emplace_back("Ed", d.E);
  c.strings = {{"InputName", d.input_names},
               {"OutputName", d.output_names},
               {"StateName", d.state_names},
               {"InputUnit", d.input_units},
               {"OutputUnit", d.output_units}};
  writeMat(path, c);
}

}  // namespace

void writeStateSpaceMat(const std::string& path, const StateSpace& d) { writeForms(path, d.standardForm(), d); }

void writeStateSpaceMats(const std::string& reduced_path, const StateSpace& reduced, const std::string& full_path,
                         const StateSpace& full) {
  const ProgressStage stage(strf("writing the reduced model (%d states) and the full one (%d states)", reduced.numStates(),
                                 full.numStates()));
  StateSpace full_standard;
  tbb::parallel_invoke([&] { writeStateSpaceMat(reduced_path, reduced); }, [&] { full_standard = full.standardForm(); });
  writeForms(full_path, std::move(full_standard), full);
}

}  // namespace mmv

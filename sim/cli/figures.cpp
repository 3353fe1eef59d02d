// The renders plugin, loaded on the first figure (sim/cli/figures.hpp).
#include "sim/cli/figures.hpp"

#include <mutex>

#include "sim/core/errors.hpp"
#include "sim/core/plugins.hpp"

namespace mmv::figures {

namespace {

const Api& api() {
  static const Api* table = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
#ifdef MMVLAB_FIGURES_PLUGIN
    const std::string built = MMVLAB_FIGURES_PLUGIN;
#else
    const std::string built;
#endif
    table = static_cast<const Api*>(loadPluginTable(
        "libmmvlab_figures.so", built, "mmvlab_figures_api",
        [](const void* t) { return static_cast<const Api*>(t)->version == kApiVersion; }, "figures plugin", failure));
    if (table) table->adopt_progress(progressState());
  });
  if (!table) throw UnavailableError("figures need libmmvlab_figures.so (OpenCV, OSMesa): tried " + failure);
  return *table;
}

/// A figure is an output: whatever the plugin throws while drawing or writing one (an
/// encoder that fails, a full disk) is an OutputError, exit 73, here at the boundary
/// (its own copy of our error types may not match ours across the shared object).
template <class F>
void drawing(F&& f) {
  try {
    f();
  } catch (const UnavailableError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

void linePlot(const std::string& path, const std::vector<render::Series>& series, const std::string& title,
              const std::string& x_label, const std::string& y_label, bool log_y, bool log_x) {
  drawing([&] { api().line_plot(path, series, title, x_label, y_label, log_y, log_x); });
}

void heatmap(const std::string& path, const Eigen::MatrixXd& values, const std::vector<std::string>& row_labels,
             const std::vector<std::string>& col_labels, const std::string& title, const std::string& row_axis,
             const std::string& col_axis, double vmin, double vmax) {
  drawing([&] { api().heatmap(path, values, row_labels, col_labels, title, row_axis, col_axis, vmin, vmax); });
}

void bode(const std::string& path, const std::vector<render::BodeTrace>& traces, const std::string& title, const std::string& x_label,
          const std::vector<double>& markers) {
  drawing([&] { api().bode(path, traces, title, x_label, markers); });
}

void framePng(const std::string& path, const DrawList& list, const Camera& camera, const FrameSize& size) {
  drawing([&] { api().frame_png(path, list, camera, size); });
}

void contactSheetPng(const std::string& path, const std::vector<DrawList>& lists, const std::vector<Camera>& cameras,
                     const FrameSize& size, int columns) {
  drawing([&] { api().contact_sheet_png(path, lists, cameras, size, columns); });
}

void summaryPng(const std::string& path, const std::string& title, const std::vector<std::string>& images,
                const std::vector<std::string>& lines) {
  drawing([&] { api().summary_png(path, title, images, lines); });
}

int renderCommand(const cli::RenderArgs& args) { return api().render_command(args); }

}  // namespace mmv::figures

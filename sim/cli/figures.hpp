#pragma once
/// Figures and frames, drawn by the renders plugin (libmmvlab_figures.so: renders/ with
/// OpenCV and OSMesa) that the executable loads on the first figure it writes. A
/// command that writes no image never loads the image stack: `mmvlab` itself links
/// neither OpenCV nor OSMesa (the plugin's 39 shared libraries, about 70 ms to load;
/// docs/benchmarks.md). Every function throws UnavailableError (exit 69) when the
/// plugin cannot be loaded, and what renders/ throws otherwise.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "renders/plot.hpp"  // plain data: Series, BodeTrace
#include "sim/core/drawing.hpp"
#include "sim/core/progress.hpp"

namespace mmv::cli {
struct RenderArgs;
}

namespace mmv::figures {

/// renders/plot.hpp, through the plugin.
void linePlot(const std::string& path, const std::vector<render::Series>& series, const std::string& title,
              const std::string& x_label, const std::string& y_label, bool log_y = false, bool log_x = false);
void heatmap(const std::string& path, const Eigen::MatrixXd& values, const std::vector<std::string>& row_labels,
             const std::vector<std::string>& col_labels, const std::string& title, const std::string& row_axis,
             const std::string& col_axis, double vmin = 0.0, double vmax = 1.0);
void bode(const std::string& path, const std::vector<render::BodeTrace>& traces, const std::string& title, const std::string& x_label,
          const std::vector<double>& markers = {});

struct FrameSize {
  int width = 1280, height = 720, supersample = 3;
};
/// One off-screen frame of `list` as `camera` sees it, as a PNG.
void framePng(const std::string& path, const DrawList& list, const Camera& camera, const FrameSize& size);
/// Frames side by side, `columns` per row, as one PNG.
void contactSheetPng(const std::string& path, const std::vector<DrawList>& lists, const std::vector<Camera>& cameras,
                     const FrameSize& size, int columns);

/// renders/summary.hpp: a one-page summary of figures already written (`images`, read
/// back from their files) and lines of text, as a PNG.
void summaryPng(const std::string& path, const std::string& title, const std::vector<std::string>& images,
                const std::vector<std::string>& lines);

/// `mmvlab render` (sim/cli/render_command.cpp, in the plugin): its exit code.
int renderCommand(const cli::RenderArgs& args);

/// The table of functions the plugin exports as `mmvlab_figures_api` (C linkage).
struct Api {
  int version;
  void (*line_plot)(const std::string&, const std::vector<render::Series>&, const std::string&, const std::string&,
                    const std::string&, bool, bool);
  void (*heatmap)(const std::string&, const Eigen::MatrixXd&, const std::vector<std::string>&, const std::vector<std::string>&,
                  const std::string&, const std::string&, const std::string&, double, double);
  void (*bode)(const std::string&, const std::vector<render::BodeTrace>&, const std::string&, const std::string&,
               const std::vector<double>&);
  void (*frame_png)(const std::string&, const DrawList&, const Camera&, const FrameSize&);
  void (*contact_sheet_png)(const std::string&, const std::vector<DrawList>&, const std::vector<Camera>&, const FrameSize&, int);
  int (*render_command)(const cli::RenderArgs&);
  /// The plugin's stages (a history's frames) recorded in the host's progress state,
  /// which the host's watchdog prints (sim/core/progress.hpp).
  void (*adopt_progress)(ProgressState*);
  void (*summary_png)(const std::string&, const std::string&, const std::vector<std::string>&, const std::vector<std::string>&);
};
constexpr int kApiVersion = 4;

}  // namespace mmv::figures

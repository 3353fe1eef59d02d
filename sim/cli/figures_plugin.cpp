// libmmvlab_figures.so: renders/ behind the table of sim/cli/figures.hpp. Built with
// its own copy of mmvlab's libraries (hidden: only the table is exported), OpenCV
// and OSMesa. What crosses the boundary is plain data and std exceptions.
#include <cstdlib>

#include "renders/frame.hpp"
#include "renders/layout.hpp"
#include "renders/plot.hpp"
#include "renders/summary.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"

namespace mmv::figures {
namespace {

void framePngImpl(const std::string& path, const DrawList& list, const Camera& camera, const FrameSize& size) {
  render::writePng(path, render::renderFrame(list, camera, {size.width, size.height, size.supersample}));
}

void contactSheetImpl(const std::string& path, const std::vector<DrawList>& lists, const std::vector<Camera>& cameras,
                      const FrameSize& size, int columns) {
  std::vector<cv::Mat> tiles;
  for (std::size_t i = 0; i < lists.size(); ++i) tiles.push_back(render::renderFrame(lists[i], cameras[i], {size.width, size.height, size.supersample}));
  render::writePng(path, render::contactSheet(tiles, columns));
}

// The figure harness (tests/figures/figure_layout.sh) asks each figure's layout by name.
[[maybe_unused]] const bool kLayoutLog = [] {
  if (const char* path = std::getenv("MMVLAB_FIGURE_LAYOUT")) render::setLayoutLog(path);
  return true;
}();

const Api kApi{kApiVersion,  render::writeLinePlotPng, render::writeHeatmapPng, render::writeBodePng, framePngImpl,
               contactSheetImpl, cli::runRenderCommand, adoptProgressState, render::writeSummaryPng};

}  // namespace
}  // namespace mmv::figures

extern "C" __attribute__((visibility("default"))) const mmv::figures::Api* mmvlab_figures_api() { return &mmv::figures::kApi; }

// mmvlab render --history RUN_DIR: frames of a `simulate` run (a slew, a table
// excitation) redrawn from its recorded coordinates (RUN_DIR/states.csv) on the model
// of the run's own scene copy and segments (RUN_DIR/scene.yaml, run.json), with an
// optional inset of chosen history.csv columns (sensor signals, torques, tips).
#include <algorithm>
#include <cmath>

#include "sim/cli/commands.hpp"
#include "sim/cli/render_common.hpp"
#include "sim/core/text.hpp"
#include "sim/io/article_drawing.hpp"
#include "sim/io/run_dir.hpp"
#include "sim/model/article_builder.hpp"

namespace mmv::cli {
namespace {

constexpr int kMaxFrames = 20000;  ///< about 11 minutes at 30 frames/s.

/// --traces: a history.csv column by its name, or a sensor's column by the sensor's name.
std::vector<render::Trace> tracesFor(const RunDir& run, const std::vector<std::string>& names) {
  std::vector<render::Trace> out;
  for (const auto& name : names) {
    int col = run.history.column(name);
    for (const auto& s : run.scene.sensors)
      if (col < 0 && s.name == name)
        for (std::size_t c = 0; c < run.history.columns.size(); ++c)
          if (run.history.columns[c].rfind(name + "_", 0) == 0) col = static_cast<int>(c);
    if (col <= 0) {
      std::string known;
      for (const auto& s : run.scene.sensors) known += s.name + ", ";
      for (std::size_t c = 1; c < run.history.columns.size(); ++c) known += run.history.columns[c] + (c + 1 < run.history.columns.size() ? ", " : "");
      throw UsageError("--traces: no sensor or column '" + name + "' in " + run.dir + "/history.csv (known: " + known + ")");
    }
    render::Trace tr;
    tr.name = run.history.columns[static_cast<std::size_t>(col)];
    for (const auto& row : run.history.rows) {
      tr.t.push_back(row[0]);
      tr.v.push_back(row[static_cast<std::size_t>(col)]);
    }
    out.push_back(std::move(tr));
  }
  return out;
}

}  // namespace

void renderHistory(const RenderArgs& args, const std::string& ext) {
  if (args.segments > 0 || args.no_gravity || !args.sets.empty())
    throw UsageError("render --history: the run's own segments, gravity and overrides are used (run.json); drop --segments, --no-gravity and --set");
  render::FrameOptions size, frame;
  parseSize(args.size, size);
  frame = size;  // with traces, the article takes the left 60 % and the traces the rest
  if (!args.traces.empty()) frame.width = std::max(16, size.width * 3 / 5);
  const RunDir run = readRunDir(args.history, args.scene_path);
  const auto model = buildArticleModel(run.scene);
  checkRunModel(run, *model);
  const std::vector<render::Trace> traces = tracesFor(run, args.traces);
  const double t0 = run.states.rows.front()[0], t1 = run.states.rows.back()[0];
  SimTK::State s = model->getReferenceState();
  auto drawAt = [&](double t) {
    setRunCoordinates(run.states, t, *model, s);
    DrawList d = drawArticle(run.scene, *model, s);
    d.title += strf("  t = %.3f s", t);
    return d;
  };
  // One camera for the whole run: the presets frame where the article goes over it.
  Eigen::AlignedBox3d reach;
  for (int k = 0; k <= 24; ++k) reach.extend(drawAt(t0 + (t1 - t0) * k / 24).bounds());
  const Camera camera = chooseCamera(args.view, drawAt(t0), run.scene.views, reach);
  auto image = [&](double t) {
    const cv::Mat article = render::renderFrame(drawAt(t), camera, frame);
    if (traces.empty()) return article;
    cv::Mat img;
    cv::hconcat(article, render::tracePanel(traces, t, cv::Size(size.width - frame.width, size.height)), img);
    return img;
  };
  if (ext == ".png") {
    const double t = args.at < 0 ? t1 : args.at;
    if (t < t0 || t > t1) throw UsageError(strf("--at %g: the run spans %g to %g s", t, t0, t1));
    const cv::Mat img = image(t);
    writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    return;
  }
  if (args.at >= 0) throw UsageError("--at draws one frame: write a .png");
  const double frames = std::floor((t1 - t0) / args.speed * args.fps) + 1;
  if (frames > kMaxFrames)
    throw UsageError(strf("render --history: %.0f frames at %g frames/s and speed %g (limit %d): lower --fps or raise --speed",
                          frames, args.fps, args.speed, kMaxFrames));
  writeAtomically(args.out, args.force, [&](const std::string& p) {
    render::VideoSink video(p, args.fps, cv::Size(size.width, size.height));
    for (int k = 0; k < static_cast<int>(frames); ++k) video.write(image(t0 + k * args.speed / args.fps));
  });
}

}  // namespace mmv::cli

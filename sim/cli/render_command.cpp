// mmvlab render: off-screen frames of the article (sim/view/article_drawing.hpp) or the
// HAM-SAS isolator (sim/view/hamsas_drawing.hpp) drawn by renders/frame.hpp: the still
// scene, a mode, a contact sheet of modes, or a mode's cycle, by the output's extension.
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <iostream>
#include <sstream>

#include "renders/frame.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/progress.hpp"
#include "sim/cli/render_common.hpp"
#include "sim/view/article_drawing.hpp"
#include "sim/view/hamsas_drawing.hpp"

namespace mmv::cli {
namespace {

namespace fs = std::filesystem;

/// "3" -> {3}; "1-6" -> {1..6} (1-based, within the model's modes).
std::vector<int> parseModes(const std::string& text, int available) {
  const auto dash = text.find('-');
  char *e1 = nullptr, *e2 = nullptr;
  const long a = std::strtol(text.c_str(), &e1, 10);
  const long b = dash == std::string::npos ? a : std::strtol(text.c_str() + dash + 1, &e2, 10);
  const bool ok = !text.empty() && (dash == std::string::npos ? *e1 == '\0' : (e1 == text.c_str() + dash && *e2 == '\0'));
  if (!ok || a < 1 || b < a) throw UsageError("--mode: expected a mode number or a range like 1-6 (got " + text + ")");
  if (b > available) throw UsageError("--mode " + text + ": the model has " + std::to_string(available) + " modes");
  std::vector<int> out;
  for (long m = a; m <= b; ++m) out.push_back(static_cast<int>(m));
  return out;
}

std::string extensionOf(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  if (ext != ".png" && ext != ".mp4" && ext != ".avi" && ext != ".pvd")
    throw UsageError("--out " + path + ": the extension says what to write: .png (a frame or a contact sheet), .mp4 or .avi, "
                     "or .pvd (a run's frames for ParaView, with --history)");
  return ext;
}


/// What a render draws, for either kind of scene: the static frame and mode frames.
struct Drawings {
  int modes = 0;
  std::function<DrawList()> still;
  std::function<DrawList(ModeNumber mode, double phase, bool short_title)> mode;
};

void writeFrames(const RenderArgs& args, const std::string& ext, const Drawings& dr, const std::vector<CameraView>& views) {
  render::FrameOptions frame;
  parseSize(args.size, frame, ext);
  auto cameraFor = [&](const DrawList& d) { return chooseCamera(args.view, d, views); };
  if (args.mode.empty()) {
    if (ext != ".png") throw UsageError("--out " + args.out + ": a video needs --mode K (the mode's cycle)");
    DrawList d = dr.still();
    d.title += "  (" + args.view + " view)";
    const cv::Mat img = render::renderFrame(d, cameraFor(d), frame);
    writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    return;
  }
  const std::vector<int> modes = parseModes(args.mode, dr.modes);
  if (ext == ".png") {
    checkSheetPixels(args.size, args.mode, modes.size(), frame);
    std::vector<cv::Mat> tiles;
    const ProgressStage stage("drawing the modes");
    for (int m : modes) {
      progressCount(static_cast<long>(tiles.size()) + 1, static_cast<long>(modes.size()), "mode");
      const DrawList d = dr.mode(ModeNumber(m), 1.0, modes.size() > 1);
      tiles.push_back(render::renderFrame(d, cameraFor(d), frame));
    }
    const cv::Mat img = tiles.size() == 1 ? tiles[0] : render::contactSheet(tiles, std::min<int>(3, tiles.size()));
    writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    return;
  }
  if (modes.size() != 1) throw UsageError("--mode " + args.mode + ": a video shows one mode's cycle");
  const Camera cam = cameraFor(dr.mode(ModeNumber(modes[0]), 1.0, false));  // one camera for every frame
  frame.supersample = kVideoSupersample;
  writeAtomically(args.out, args.force, [&](const std::string& p) {
    render::VideoSink video(p, 24.0, cv::Size(frame.width, frame.height));
    const ProgressStage stage("drawing the mode's cycle");
    for (int i = 0; i < 48; ++i) {
      progressCount(i + 1, 48, "frame");
      video.write(render::renderFrame(dr.mode(ModeNumber(modes[0]), std::sin(2 * M_PI * i / 48), false), cam, frame));
    }
    video.close();
  });
}

}  // namespace

int runRenderCommand(const RenderArgs& given) {
  return guarded([&] {
    RenderArgs args = given;  // the view resolved below
    if (args.out.empty()) throw UsageError("render: --out FILE is required (.png, .mp4 or .avi)");
    const std::string ext = extensionOf(args.out);
    render::FrameOptions check;
    parseSize(args.size, check, ext);  // a bad size is refused before any work
    checkOutputFile(args.out, args.force);  // and an --out it may not write (a link, a FIFO, a file without --force)
    if (!args.history.empty()) {
      if (!args.mode.empty()) throw UsageError("render: --mode and --history draw different things; give one");
      renderHistory(args, ext);
      std::cerr << "mmvlab: wrote " << args.out << '\n';
      return kOk;
    }
    if (!args.traces.empty() || args.at >= 0) throw UsageError("render: --traces and --at apply to --history RUN_DIR");
    if (ext == ".pvd") throw UsageError("--out " + args.out + ": a .pvd is a run's frames for ParaView: give --history RUN_DIR (a mode's shape: modes --out writes modes.vtp)");
    const Scene loaded = loadScene(args);
    // The spatial article moves out of its plane, which the front view looks along.
    const auto* article = std::get_if<ArticleScene>(&loaded);
    if (args.view.empty()) args.view = article && article->article.model == ArticleModel::Spatial ? "iso" : "front";
    Drawings dr;
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) {
      const HamsasModes modes = analyseHamsas(h->isolator);
      dr.modes = static_cast<int>(modes.modes.size());
      dr.still = [&] { return drawHamsas(*h, modes); };
      dr.mode = [&](ModeNumber m, double phase, bool short_title) {
        return drawHamsas(*h, modes, m, phase, args.scale, short_title);
      };
      writeFrames(args, ext, dr, {});
    } else {
      const ArticleScene& scene = std::get<ArticleScene>(loaded);
      const SolvedScene solved = solveScene(scene);
      std::map<ModeNumber, std::unique_ptr<ModeFrames>> cache;  // each mode's shape computed once
      dr.modes = static_cast<int>(solved.modes.omega2.size());
      dr.still = [&] {
        SimTK::State st = solved.equilibrium.state;
        solved.model->getSystem().realize(st, SimTK::Stage::Position);
        DrawList d = drawArticle(scene, *solved.model, st);
        d.title += "  (static equilibrium)";
        return d;
      };
      dr.mode = [&](ModeNumber m, double phase, bool short_title) {
        auto& f = cache[m];
        if (!f) f = std::make_unique<ModeFrames>(scene, solved, m, args.scale);
        return f->frame(phase, short_title);
      };
      writeFrames(args, ext, dr, scene.views);
    }
    std::cerr << "mmvlab: wrote " << args.out << '\n';
    return kOk;
  });
}

}  // namespace mmv::cli

// mmvlab render: off-screen frames of the article (sim/io/article_drawing.hpp) drawn
// by renders/frame.hpp: the article with its sensors, a mode, a contact sheet of
// modes, or a mode's animated cycle, by the output's extension.
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "renders/frame.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/article_drawing.hpp"

namespace mmv::cli {
namespace {

namespace fs = std::filesystem;

/// "1280x720" -> width, height (16..8192 each).
void parseSize(const std::string& text, render::FrameOptions& o) {
  const auto x = text.find('x');
  char *e1 = nullptr, *e2 = nullptr;
  const long w = x == std::string::npos ? 0 : std::strtol(text.c_str(), &e1, 10);
  const long h = x == std::string::npos ? 0 : std::strtol(text.c_str() + x + 1, &e2, 10);
  if (x == std::string::npos || e1 != text.c_str() + x || *e2 != '\0' || w < 16 || h < 16 || w > 8192 || h > 8192)
    throw UsageError("--size: expected WIDTHxHEIGHT in pixels, 16 to 8192 each (got " + text + ")");
  o.width = static_cast<int>(w);
  o.height = static_cast<int>(h);
}

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
  if (ext != ".png" && ext != ".mp4" && ext != ".avi")
    throw UsageError("--out " + path + ": the extension says what to write: .png (a frame or a contact sheet), .mp4 or .avi");
  return ext;
}

/// Writes through a temporary name in the same directory, renamed on success, so a
/// failed or interrupted run leaves no partial file; refuses to replace a file unless
/// --force.
template <class Write>
void writeAtomically(const std::string& path, bool force, Write write) {
  const fs::path target(path);
  std::error_code ec;
  if (fs::exists(target, ec) && !force) throw OutputError(path + ": exists (use --force to replace it)");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw OutputError(path + ": the directory " + dir.string() + " does not exist");
  const fs::path tmp = dir / (".mmvlab-" + std::to_string(::getpid()) + "-" + target.filename().string());
  try {
    write(tmp.string());
  } catch (const std::exception& e) {
    fs::remove(tmp, ec);
    throw OutputError(e.what());
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw OutputError(path + ": cannot write (" + ec.message() + ")");
  }
}

}  // namespace

int runRenderCommand(const RenderArgs& args) {
  return guarded([&] {
    if (args.out.empty()) throw UsageError("render: --out FILE is required (.png, .mp4 or .avi)");
    const std::string ext = extensionOf(args.out);
    render::FrameOptions frame;
    parseSize(args.size, frame);
    const ArticleScene scene = loadArticleScene(args, "render");
    const SolvedScene solved = solveScene(scene);
    Camera camera;
    auto cameraFor = [&](const DrawList& d) {
      if (!presetCamera(args.view, d.bounds(), camera))
        throw UsageError("--view: unknown view '" + args.view + "' (known: front, side, top, iso)");
      return camera;
    };
    if (args.mode.empty()) {
      if (ext != ".png") throw UsageError("--out " + args.out + ": a video needs --mode K (the mode's cycle)");
      SimTK::State st = solved.equilibrium.state;
      solved.model->getSystem().realize(st, SimTK::Stage::Position);
      DrawList d = drawArticle(scene, *solved.model, st);
      d.title += "  (static equilibrium; " + args.view + " view)";
      const cv::Mat img = render::renderFrame(d, cameraFor(d), frame);
      writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    } else {
      const std::vector<int> modes = parseModes(args.mode, static_cast<int>(solved.modes.omega2.size()));
      if (ext == ".png") {
        std::vector<cv::Mat> tiles;
        for (int m : modes) {
          const DrawList d = drawMode(scene, solved, m - 1, 1.0, args.scale, nullptr, modes.size() > 1);
          tiles.push_back(render::renderFrame(d, cameraFor(d), frame));
        }
        const cv::Mat img = tiles.size() == 1 ? tiles[0] : render::contactSheet(tiles, std::min<int>(3, tiles.size()));
        writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
      } else {
        if (modes.size() != 1) throw UsageError("--mode " + args.mode + ": a video shows one mode's cycle");
        const ModeFrames mode(scene, solved, modes[0] - 1, args.scale);
        const Camera cam = cameraFor(mode.frame(1.0));  // one camera for every frame
        std::vector<cv::Mat> frames;
        for (int i = 0; i < 48; ++i) frames.push_back(render::renderFrame(mode.frame(std::sin(2 * M_PI * i / 48)), cam, frame));
        writeAtomically(args.out, args.force, [&](const std::string& p) { render::writeVideo(p, frames, 24.0); });
      }
    }
    std::cerr << "mmvlab: wrote " << args.out << '\n';
    return kOk;
  });
}

}  // namespace mmv::cli

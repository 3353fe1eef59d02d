// mmvlab render: off-screen frames of the article (sim/io/article_drawing.hpp) or the
// HAM-SAS isolator (sim/io/hamsas_drawing.hpp) drawn by renders/frame.hpp: the still
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
#include "sim/io/article_drawing.hpp"
#include "sim/io/hamsas_drawing.hpp"

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

namespace {

/// What a render draws, for either kind of scene: the static frame and mode frames.
struct Drawings {
  int modes = 0;
  std::function<DrawList()> still;
  std::function<DrawList(int mode, double phase, bool short_title)> mode;
};

void writeFrames(const RenderArgs& args, const std::string& ext, const Drawings& dr, const std::vector<CameraView>& views) {
  render::FrameOptions frame;
  parseSize(args.size, frame);
  auto cameraFor = [&](const DrawList& d) {
    Camera camera;
    if (args.view.rfind("sensor:", 0) == 0) {
      // A close front view of one labelled sensor: the 0.6 m around it fill the frame.
      const std::string name = args.view.substr(7);
      std::string known;
      for (const auto& l : d.labels) {
        const std::string label = l.text.substr(0, l.text.find(' '));
        if (label == name) {
          presetCamera("front", Eigen::AlignedBox3d(l.at - Eigen::Vector3d::Constant(0.3), l.at + Eigen::Vector3d::Constant(0.3)),
                       camera, d.up);
          return camera;
        }
        known += (known.empty() ? "" : ", ") + label;
      }
      throw UsageError("--view " + args.view + ": no sensor '" + name + "' in the scene (known: " +
                       (known.empty() ? "none" : known) + ")");
    }
    if (args.view == "lab") {  // the whole room, the article in it
      if (!d.hasContext()) throw UsageError("--view lab: the scene has no lab: section (docs/scene-format.md)");
      presetCamera("iso", d.bounds(true), camera, d.up);
      return camera;
    }
    std::string names;
    for (const auto& v : views) {
      if (v.name == args.view) {
        camera.eye = {v.eye[0], v.eye[1], v.eye[2]};
        camera.target = {v.target[0], v.target[1], v.target[2]};
        camera.up = Eigen::Vector3d(v.up[0], v.up[1], v.up[2]).normalized();
        camera.fov_deg = v.fov_deg;
        return camera;
      }
      names += ", " + v.name;
    }
    if (!presetCamera(args.view, d.bounds(), camera, d.up))
      throw UsageError("--view: unknown view '" + args.view + "' (known: front, side, top, iso, lab, sensor:NAME" + names + ")");
    return camera;
  };
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
    std::vector<cv::Mat> tiles;
    for (int m : modes) {
      const DrawList d = dr.mode(m - 1, 1.0, modes.size() > 1);
      tiles.push_back(render::renderFrame(d, cameraFor(d), frame));
    }
    const cv::Mat img = tiles.size() == 1 ? tiles[0] : render::contactSheet(tiles, std::min<int>(3, tiles.size()));
    writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    return;
  }
  if (modes.size() != 1) throw UsageError("--mode " + args.mode + ": a video shows one mode's cycle");
  const Camera cam = cameraFor(dr.mode(modes[0] - 1, 1.0, false));  // one camera for every frame
  std::vector<cv::Mat> frames;
  for (int i = 0; i < 48; ++i) frames.push_back(render::renderFrame(dr.mode(modes[0] - 1, std::sin(2 * M_PI * i / 48), false), cam, frame));
  writeAtomically(args.out, args.force, [&](const std::string& p) { render::writeVideo(p, frames, 24.0); });
}

}  // namespace

int runRenderCommand(const RenderArgs& args) {
  return guarded([&] {
    if (args.out.empty()) throw UsageError("render: --out FILE is required (.png, .mp4 or .avi)");
    const std::string ext = extensionOf(args.out);
    render::FrameOptions check;
    parseSize(args.size, check);  // a bad size is refused before any work
    const Scene loaded = loadScene(args);
    Drawings dr;
    if (const auto* h = std::get_if<HamsasScene>(&loaded)) {
      const HamsasModes modes = analyseHamsas(h->isolator);
      dr.modes = static_cast<int>(modes.modes.size());
      dr.still = [&] { return drawHamsas(*h, modes); };
      dr.mode = [&](int m, double phase, bool short_title) { return drawHamsas(*h, modes, m, phase, args.scale, short_title); };
      writeFrames(args, ext, dr, {});
    } else {
      const ArticleScene& scene = std::get<ArticleScene>(loaded);
      const SolvedScene solved = solveScene(scene);
      std::map<int, std::unique_ptr<ModeFrames>> cache;  // each mode's shape computed once
      dr.modes = static_cast<int>(solved.modes.omega2.size());
      dr.still = [&] {
        SimTK::State st = solved.equilibrium.state;
        solved.model->getSystem().realize(st, SimTK::Stage::Position);
        DrawList d = drawArticle(scene, *solved.model, st);
        d.title += "  (static equilibrium)";
        return d;
      };
      dr.mode = [&](int m, double phase, bool short_title) {
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

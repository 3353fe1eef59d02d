#include "sim/cli/render_common.hpp"

#include <cstdlib>

#include "sim/core/text.hpp"

namespace mmv::cli {

/// "1280x720" -> width, height (16..8192 each; an .mp4 at most 8191, MPEG-4 part 2's limit).
void parseSize(const std::string& text, render::FrameOptions& o, const std::string& ext) {
  const auto x = text.find('x');
  char *e1 = nullptr, *e2 = nullptr;
  const long w = x == std::string::npos ? 0 : std::strtol(text.c_str(), &e1, 10);
  const long h = x == std::string::npos ? 0 : std::strtol(text.c_str() + x + 1, &e2, 10);
  if (x == std::string::npos || e1 != text.c_str() + x || *e2 != '\0' || w < 16 || h < 16 || w > kMaxFrameSide || h > kMaxFrameSide)
    throw UsageError("--size: expected WIDTHxHEIGHT in pixels, 16 to 8192 each (got " + text + ")");
  if (ext == ".mp4" && (w > kMaxMp4Side || h > kMaxMp4Side))
    throw UsageError("--size " + text + ": an .mp4 video (MPEG-4 part 2) is at most " + std::to_string(kMaxMp4Side) +
                     " pixels a side: use .avi or a smaller --size");
  o.width = static_cast<int>(w);
  o.height = static_cast<int>(h);
}

void checkSheetPixels(const std::string& size_text, const std::string& mode_text, std::size_t tiles, const render::FrameOptions& o) {
  const double pixels = static_cast<double>(tiles) * o.width * o.height;
  if (pixels > kMaxImagePixels)
    throw UsageError("--mode " + mode_text + " --size " + size_text + ": a contact sheet of " + std::to_string(tiles) + " frames is " +
                     strf("%.3g", pixels / 1e6) + " Mpixel, above the limit of " + strf("%.3g", kMaxImagePixels / 1e6) +
                     " Mpixel (8192 x 8192): draw fewer modes or a smaller --size");
}

Camera chooseCamera(const std::string& view, const DrawList& d, const std::vector<CameraView>& views,
                    const Eigen::AlignedBox3d& frame) {
  Camera camera;
  if (view.rfind("sensor:", 0) == 0) {
    // A close front view of one labelled sensor: the 0.6 m around it fill the frame.
    const std::string name = view.substr(7);
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
    throw UsageError("--view " + view + ": no sensor '" + name + "' in the scene (known: " +
                     (known.empty() ? "none" : known) + ")");
  }
  if (view == "lab") {  // the whole room, the article in it
    if (!d.hasContext()) throw UsageError("--view lab: the scene has no lab: section (docs/scene-format.md)");
    presetCamera("iso", d.bounds(true), camera, d.up);
    camera.room = true;
    return camera;
  }
  std::string names;
  for (const auto& v : views) {
    if (v.name == view) {
      camera.eye = {v.eye[0], v.eye[1], v.eye[2]};
      camera.target = {v.target[0], v.target[1], v.target[2]};
      camera.up = Eigen::Vector3d(v.up[0], v.up[1], v.up[2]).normalized();
      camera.fov_deg = v.fov_deg;
      return camera;
    }
    names += ", " + v.name;
  }
  if (!presetCamera(view, frame.isEmpty() ? d.bounds() : frame, camera, d.up))
    throw UsageError("--view: unknown view '" + view + "' (known: front, side, top, iso, lab, sensor:NAME" + names + ")");
  return camera;
}

}  // namespace mmv::cli

#pragma once
/// A drawing list: what a 3-D frame shows, as plain data (SI units, world frame).
/// sim/view builds one from a model and a state (sim/view/article_drawing.hpp); renders/
/// draws it off-screen (renders/frame.hpp). Nothing here knows Simbody or OpenGL.

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace mmv {

struct DrawItem {
  enum class Shape {
    Box,       ///< size: lengths along the pose's x, y, z (m).
    Cylinder,  ///< axis along the pose's x; size: length, diameter, (unused) (m).
    Sphere,    ///< size[0]: diameter (m).
  };
  Shape shape = Shape::Box;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  ///< the item's centre and axes in the world.
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  std::array<float, 4> rgba{0.7f, 0.7f, 0.7f, 1.0f};  ///< alpha < 1: translucent (drawn after the opaque items).
  /// When set (finite), the colour comes from the list's colour bar at this value
  /// (renders/ maps it with a standard colormap) and rgba only gives the alpha.
  double value = std::numeric_limits<double>::quiet_NaN();
  /// Surroundings (the lab's floor, platform, ceiling): drawn, but the camera presets
  /// frame the article without them (DrawList::bounds). Translucent surroundings never
  /// grey what is not context (the article under the platform stays in its colours).
  bool context = false;
  /// The room's far surfaces (floor, ceiling): drawn only by a camera that shows the
  /// whole room (Camera::room, `--view lab`); a framed view would cut them at its edge.
  bool room = false;
};

/// Text anchored at a world point (drawn in 2-D over the frame, with a leader dot).
struct DrawLabel {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  std::string text;
  std::array<float, 4> rgba{0.1f, 0.1f, 0.1f, 1.0f};
  bool context = false;  ///< as DrawItem::context.
  bool room = false;     ///< as DrawItem::room.
};

/// A colour scale shown beside the frame: what the items' colours mean.
struct ColorBar {
  std::string title;   ///< e.g. "|u| (m, shape scaled x 0.5)".
  double min = 0, max = 1;
};

struct DrawList {
  std::vector<DrawItem> items;
  std::vector<DrawLabel> labels;
  std::vector<std::pair<std::string, std::array<float, 4>>> legend;  ///< name and swatch colour.
  std::string title;
  bool has_color_bar = false;
  ColorBar color_bar;
  /// The world's vertical (the article: +y, its plane of motion x-y; HAM-SAS: +z).
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  /// Axis-aligned bounds of what is drawn (m), for the camera presets: the items and
  /// labels that are not context, or everything with `with_context`.
  Eigen::AlignedBox3d bounds(bool with_context = false) const;
  bool hasContext() const;
};

/// A pose at `centre` with its x axis along `dir` and its z axis as near world z as
/// possible (a beam piece, a cylinder's axis).
Eigen::Isometry3d poseAlong(const Eigen::Vector3d& centre, const Eigen::Vector3d& dir);

/// A camera looking from `eye` at `target`, `up` up, with a vertical field of view.
struct Camera {
  Eigen::Vector3d eye{0, 0, 5}, target{0, 0, 0}, up{0, 1, 0};
  double fov_deg = 30;
  bool room = false;  ///< shows the whole room: draws the items and labels marked `room`.
  /// Set by presetCamera: the preset and the bounds it frames, so that the renderer can
  /// frame them again into the part of its picture the legend and colour bar leave free
  /// (renders/framing.cpp). Empty: the camera is used as it stands (a scene's `views:`).
  std::string fit_preset;
  Eigen::AlignedBox3d fit_bounds;
  Eigen::Vector3d fit_up = Eigen::Vector3d::UnitY();
};

/// Where in the picture a preset puts what it frames, in normalized device coordinates
/// (-1..1, y up), and the picture's width / height.
struct ViewWindow {
  double x0 = -1, x1 = 1, y0 = -1, y1 = 1;
  double aspect = 16.0 / 9;
};

/// The presets for a world whose vertical is `up` (+y or +z): "front" (for +y up:
/// looking along -z at the x-y plane of motion; for +z up: along +y), "side" (along
/// -x), "top" (down the vertical), "iso". The camera frames `bounds` (its eight corners,
/// in perspective) so that they fill 90 % of `window`'s width or height. Returns false
/// for an unknown name.
bool presetCamera(const std::string& name, const Eigen::AlignedBox3d& bounds, Camera& camera,
                  const Eigen::Vector3d& up = Eigen::Vector3d::UnitY(), const ViewWindow& window = ViewWindow{});

}  // namespace mmv

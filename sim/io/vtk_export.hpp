#pragma once
/// The article and its modes as a VTK XML PolyData file (.vtp) that ParaView opens:
/// `modes --out` writes it as modes.vtp (docs/outputs.md).
///
///  - Points: every point of the modes report (joints and each link's root, hinges and
///    tip) at the deflected equilibrium, world frame, metres.
///  - Lines: one polyline per link through its points, root to tip (cell data
///    `link_index`, the link's place in the scene's `links:`); Verts: the joints.
///  - Point data: `deflection_m` (the equilibrium minus the unbent shape), the link's
///    section depth in the bending plane and width out of it (`section_depth_m`,
///    `section_width_m`; a round rod's diameter for both; an explicit section's
///    equal-area circle), and `tube_radius_m` (half the depth: ParaView's Tube filter,
///    "Vary Radius: By Absolute Scalar"); then one 3-component array per mode, the
///    translation per unit modal coordinate of the mass-normalised shape (kg^-1/2, as
///    modes.json's `shape`), named `modeNN_F Hz` with the frequency (`modeNN_rigid`,
///    `modeNN_unstable`), for Warp By Vector.
///  - Field data: `frequency_hz` per mode (negative: unstable), `damping_ratio` per mode
///    when the scene is damped, and `link_names` (the links in `link_index` order).
/// Doubles are written with 17 significant digits, so the file holds the JSON's values.
///
/// `place-sensors --out` on an article writes sensors.vtp: one vertex per channel (the
/// rows of channels.csv, in order) at its station, world frame; point data `direction`
/// (the measuring axis, a unit vector: ParaView's Glyph filter draws arrows along it),
/// `channel`, `node` (the test geometry's), `kept_from_scene` (1: a scene sensor kept in
/// advance), and each target mode's translation at the station (`modeNN_F Hz`, as the
/// test geometry's predicted shapes); field data `target_frequency_hz`, `channels`
/// ("station axis" per point) and `scene`.

#include <string>
#include <utility>
#include <vector>

#include "article/article_spec.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/scene/scene.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

std::string modesVtp(const ModesReport& report, const ArticleSpec& article);
/// A HAM-SAS scene's modes.vtp: every moving body (not the base, whose motion is
/// prescribed) as its equivalent box (article/spatial_spec.hpp, as the renders draw it)
/// at the design configuration: 8 corner points and 6 quadrilaterals a body, point and
/// cell data `body_index` (its place in field data `body_names`, the base being 0); one
/// 3-component array per mode (`modeNN_FHz`, `modeNN_unstable`): each corner's
/// translation per unit modal coordinate of the mass-normalised shape, t + w x r from
/// the body's translation t and small rotation w (modes.json's `shape`) and the corner's
/// offset r from its mass centre; field data `frequency_hz` and `scene`. The first
/// `max_modes` modes (0: all).
std::string hamsasModesVtp(const HamsasScene& scene, const HamsasModes& h, int max_modes);
std::string placementVtp(const PlacementStudy& study);

/// A run for ParaView (`render --history RUN --out FILE.pvd`): each frame the article's
/// points (`names`, xyz in metres, world frame) at `time_s`, linked per link as in
/// modes.vtp with the same section arrays, point data `displacement_m` (from the run's
/// first frame) and field data `TimeValue`; the collection lists the frames with their
/// times (files relative to the .pvd).
std::string articlePoseVtp(const std::vector<std::string>& names, const std::vector<double>& xyz,
                           const std::vector<double>& displacement, const ArticleSpec& article, double time_s);
std::string pvdCollection(const std::vector<std::pair<double, std::string>>& frames);
/// A HAM-SAS run's frame: the boxes of hamsasModesVtp moved by each body's recorded
/// motion (translation and rotation vector, world; the base's included), true to scale:
/// hamsasCorners gives their corners (xyz, m), hamsasPoseVtp the file with
/// `displacement_m` (from the run's first frame) and field data `TimeValue`.
std::vector<double> hamsasCorners(const SpatialSpec& spec, const std::vector<Eigen::Matrix<double, 6, 1>>& motion);
std::string hamsasPoseVtp(const SpatialSpec& spec, const std::vector<double>& xyz, const std::vector<double>& displacement,
                          double time_s);

}  // namespace mmv

#pragma once
/// Stations: points of the physical article named by where they are, not by the mesh.
///
///     LINK@DIST m          e.g. link1@1.83m  (distance from the link's root, m)
///     LINK@FRACTION        e.g. link1@0.75   (fraction of the link's length, 0..1)
///     ...+OFFSETm / -OFFSETm   e.g. link1@0.75+0.0127m (across the section, along
///                          the link's local y; the top face of link 1's tube)
///     ...+Ym+Zm            e.g. link3a@0.5+0m+0.004m (and along the section's normal,
///                          the link's local z: out of the plane; spatial model only)
///
/// A station's motion is interpolated from the discretized link with the beam's cubic
/// (Hermite) shape functions (sim/model/stations.hpp), so it converges as the segments
/// per link grow, where a hinge name (`link1.h12`) moves along the link as the mesh
/// changes. Hinge and tip names stay valid as aliases of the mesh's points.

#include <optional>
#include <string>
#include <utility>

#include "sim/scene/scene.hpp"

namespace mmv {

struct StationSpec {
  std::string name;    ///< as written.
  std::string link;    ///< a link (or branch) of the article.
  double x = 0;        ///< m from the link's root, 0 <= x <= length.
  double offset = 0;   ///< m across the section (local y).
  double offset_z = 0; ///< m along the section's normal (local z, out of the plane: spatial model).
};

/// True when `name` is written as a station (it contains '@').
bool isStationName(const std::string& name);

/// Parses a station of `article`. On a malformed name, an unknown link or a position
/// outside the link, returns nothing and sets `error` (one line, with the valid range).
std::optional<StationSpec> parseStation(const std::string& name, const ArticleSpec& article, std::string& error);

/// A bending strain gauge's or piezo film's span: two stations on one flexible link's
/// axis, and the distance `surface_m` of the section's face from its neutral axis: in
/// the plane (the +y face) half the depth h, out of it (the +z face, spatial model) half
/// the width b; a rod's radius either way. Its mean surface strain is
/// -surface_m (theta_b - theta_a) / (x_b - x_a) for the in-plane rotations theta, and
/// +surface_m (phi_b - phi_a) / (x_b - x_a) for the rotations phi out of the plane
/// (sim/model/stations.hpp strainRow).
struct StrainSpan {
  std::string link;
  double x_a = 0, x_b = 0, surface_m = 0;
  bool out_of_plane = false;
};
/// Nothing, with the reason, for a station with an offset, two links, an empty span, a
/// rigid link, a section without depth (an explicit one) or bending out of the plane of
/// a planar article.
std::optional<StrainSpan> strainSpan(const ArticleSpec& article, const std::string& a, const std::string& b, std::string& why,
                                     bool out_of_plane = false);
/// "in" or "out" (the bending a strain reads), else nothing.
std::optional<bool> strainBendsOutOfPlane(const std::string& word);

/// Where a point sits along its link, (link, m from its root): a station (its offset
/// across the section dropped), or a link's root or tip. Nothing, with the reason, for a
/// point of the mesh (a hinge, which moves along the link when the segments change) or a
/// joint's axis.
std::optional<std::pair<std::string, double>> pointAlongLink(const ArticleSpec& article, const std::string& target, std::string& why);

}  // namespace mmv

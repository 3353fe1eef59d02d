#pragma once
/// The laboratory the article is tested in (report, "Facility Layout"; docs/sources.md section 2):
/// the west high bay of MSFC Building 4619, a 53.5 ft x 29.0 ft floor with about a
/// 90 ft ceiling, an existing platform at 42.5 ft, and a 5 ft x 5 ft hole cut in the
/// platform through which the article hangs from the table and gimbal.
///
/// The report gives no plan of the platform itself (its figures 10-13 are not in our
/// copy): its extent, its thickness and how far the article's base joint sits below its
/// top are chosen here (`assumed` below) and every one can be set in the scene.
/// Frame: the article's world (x along the floor's length, y up, z across the floor);
/// the hole is centred on the article's base, the floor under it.

namespace mmv::facility {

constexpr double kFoot = 0.3048;  ///< m.

struct LabSpec {
  double floor_length = 53.5 * kFoot;   ///< m, along x (report).
  double floor_width = 29.0 * kFoot;    ///< m, along z (report).
  double ceiling_height = 90.0 * kFoot; ///< m above the floor (report: "approximately").
  double platform_height = 42.5 * kFoot; ///< m, the platform's top above the floor (report).
  double hole_side = 5.0 * kFoot;        ///< m, the square hole in the platform (report).
  // Assumed (not in the report):
  double platform_length = 20.0 * kFoot;  ///< m along x (assumed).
  double platform_width = 29.0 * kFoot;   ///< m along z: the floor's width (assumed).
  double platform_thickness = 0.3;        ///< m (assumed).
  double base_below_platform = 0.6;       ///< m, the base joint below the platform's top: the table and gimbal between (assumed).
};

/// The heights (world y, m) of the floor, the platform's top and the ceiling for an
/// article whose base joint is at height `base_y`.
struct LabLevels {
  double floor, platform_top, ceiling;
};

inline LabLevels labLevels(const LabSpec& lab, double base_y) {
  const double top = base_y + lab.base_below_platform;
  const double floor = top - lab.platform_height;
  return {floor, top, floor + lab.ceiling_height};
}

}  // namespace mmv::facility

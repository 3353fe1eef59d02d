#pragma once
/// The LIGO HAM-SAS seismic isolator (docs/sources.md section 3) as a spatial rigid-body
/// network (article/spatial_spec.hpp): 11 bodies -- the base (prescribed ground
/// motion), 4 inverted-pendulum (IP) legs with counterweights, 4 little pendulums (LP),
/// the spring box (SB) and the optical table (OT) with its payload.
///
/// Topology (docs/hamsas.md explains the choice): each IP leg stands on the base through
/// a flex joint (an effective spherical joint plus an angular spring with viscous
/// damping); a little pendulum hangs from each leg's top through an effective spherical
/// joint and carries the spring box through another; 4 MGAS springs (3-D linear springs,
/// diagonal stiffness) carry the optical table on the spring box. Effective spherical
/// joints are 3-D linear springs of `joint_stiffness` (the authors' 1e8 N/m), or ideal
/// ball joints. 8 displacement sensors with co-located force actuators measure the spring
/// box relative to the base: a horizontal (tangential) and a vertical one at each leg.
///
/// Coordinates: z up, origin at the IP pivots' plane above the base centre; the IP legs
/// on a diamond (x span, y span), the MGAS springs on a rectangle.

#include <string>
#include <vector>

#include "article/spatial_spec.hpp"

namespace mmv {

struct HamsasSpec {
  // Geometry (m). Published: the diamond and the rectangle.
  double ip_diamond_x = 1.1, ip_diamond_y = 0.9;
  double mgas_rect_x = 1.1, mgas_rect_y = 1.0;
  double ip_length = 0.5;  ///< pivot to the leg's top.
  // IP legs.
  double ip_leg_mass = 5.0;          ///< kg, the tube, uniform over the length.
  double ip_leg_radius = 0.04;       ///< m, the tube's radius (torsional inertia).
  double counterweight_mass = 3.5;   ///< kg, a disk below the pivot (centre-of-percussion tuning).
  double counterweight_depth = 0.1;  ///< m below the pivot.
  double counterweight_radius = 0.05;
  double flex_stiffness = 2166;      ///< N*m/rad, bending of the flex joint (about x and y): tuned, IP 65 mHz.
  double flex_torsion = 100;         ///< N*m/rad, about the leg's axis.
  double flex_damping = 1.0;         ///< N*m*s/rad, bending (IP damping ratio about 1 %).
  // Little pendulums.
  double lp_length = 0.1120;  ///< m: tuned, little pendulums 22 Hz.
  double lp_mass = 0.5;     ///< kg.
  double lp_radius = 0.01;  ///< m (its inertia).
  double lp_torsion = 10;   ///< N*m/rad: the wire's torsion about its axis (otherwise a free spin).
  // Spring box.
  double sb_mass = 741.4;                     ///< kg: tuned, effective spherical joints 60 Hz.
  double sb_size_x = 1.3, sb_size_y = 1.2, sb_size_z = 0.3;  ///< m: its inertia as a uniform box.
  double sb_com_below_hang = 0.1;             ///< m: SB mass centre below the LP attachment points.
  double mgas_plane_above_sb_com = 0.1;       ///< m: the MGAS attachment plane above the SB mass centre.
  // Optical table with payload.
  double ot_mass = 1000;                      ///< kg.
  double ot_size_x = 1.9, ot_size_y = 1.7, ot_size_z = 0.3;  ///< m: its inertia as a uniform box.
  double ot_com_above_mgas = -0.00631;        ///< m: the OT mass centre above the MGAS plane: tuned, tilt 125 mHz.
  // MGAS springs (per spring).
  double mgas_vertical_stiffness = 98.70;    ///< N/m: tuned, MGAS vertical 100 mHz.
  double mgas_horizontal_stiffness = 269.0;  ///< N/m: tuned, horizontal GAS 265 mHz.
  double mgas_vertical_damping = 0, mgas_horizontal_damping = 0;  ///< N*s/m.
  // Effective spherical joints.
  double joint_stiffness = 1e8;  ///< N/m.
  double joint_damping = 1e3;    ///< N*s/m.
  bool ideal_joints = false;     ///< ideal ball joints (constraints) instead of stiff springs.
};

/// A numeric parameter of HamsasSpec by its scene key (docs/scene-format.md).
struct HamsasParameter {
  enum Sign { Positive, NonNegative, Any };
  const char* key;
  double HamsasSpec::*field;
  Sign sign;
  const char* unit;  ///< with a leading space, for messages.
};
const std::vector<HamsasParameter>& hamsasParameters();

/// The spatial network of `spec`; body 1 is the optical table (the output body).
/// Throws std::invalid_argument for a non-physical parameter (message names it).
SpatialSpec buildHamsas(const HamsasSpec& spec);

}  // namespace mmv

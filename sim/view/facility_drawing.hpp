#pragma once
/// The facility around the article, as a drawing list (sim/core/drawing.hpp): what the
/// article hangs from, and the room, each only when the scene names it.
///
/// The mount is a stack between the article's base joint and the platform's top,
/// `base_below_platform` high (facility/lab.hpp; 0.6 m when the scene has no lab):
///  - the base excitation table (BaseType::Table): a 1 m x 1 m slab, 0.1 m thick, on
///    the platform (report: horizontal x-y table, 2.3 kN payload), schematic;
///  - the gimbal (`base.gimbal`): its payload plate at the base joint and three
///    concentric rings about yaw (y), pitch (z) and roll (x), schematic, hanging from
///    the table through the hole;
///  - a post from the base to the table or the platform when nothing else carries it.
/// The lab (`lab:`): the floor, the platform at its height with its square hole
/// centred on the base (translucent, so the article shows through it from above), and
/// the ceiling (faint); labelled with their heights.

#include "sim/core/drawing.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// The mount's height (m): the base joint below the platform's top (or the table's underside).
double mountHeight(const ArticleScene& scene);

/// Adds the table, the gimbal, the post and, with `lab:`, the room. `moved`: the
/// table's displacement (world, m), which carries the gimbal too; the room stays.
void addFacility(DrawList& d, const ArticleScene& scene, const Eigen::Vector3d& moved = Eigen::Vector3d::Zero());

}  // namespace mmv

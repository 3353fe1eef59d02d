#pragma once
/// What a scene attaches to the built article: dead loads, loop closures, and (time runs
/// with a force program only) the extra shaker's armature and stinger.

#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// The scene's `loads:` (dead loads at named points, Model::addPointLoad) and `closures:`.
/// Throws SceneError when a named point does not exist with the segment counts in use.
void addLoadsAndClosures(const ArticleSpec& a, Model& model);

/// The shaker of `scene.shaker` (which has a program) as the run drives it:
///
/// - its armature, a body of the armature's mass on a slider along the force's direction,
///   on the ground (the shaker stands on the floor, not on the table); its weight is
///   carried by the shaker's suspension (a dead load cancels it), so only its inertia
///   loads the article;
/// - the stinger, stiff along its axis and free across it: a closure that holds the
///   driving point (the station at `shaker.at`) to the armature along
///   the direction, so the armature moves with it along the direction only (the linear
///   models' M + m b b^T, sim/linear/exciter.hpp);
/// - the program's force on the armature's slider (coordinate `shaker`, in metres from
///   the point the stinger meets at the scene's angles): its work enters the run's energy
///   balance as a commanded torque's does.
///
/// The driving point is the station as the linear models interpolate it between the
/// mesh nodes (sim/model/stations.hpp: the beam's Hermite functions of the two nodes'
/// positions and directions), held by a weighted closure (sim/model/weighted_closure.hpp);
/// at a mesh node, that node's point. A tree with the stinger is closed: the run holds
/// the closure as Simbody's integrators (and IDA) do, and its drift is reported.
void addShakerArmature(const ArticleScene& scene, Model& model);

}  // namespace mmv

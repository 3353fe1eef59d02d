#pragma once
/// A closure whose point A is a weighted sum of body points (Closure::points_a: a station
/// interpolated between mesh nodes with the beam's Hermite functions), held to point B of
/// another body along one direction fixed in B: the stinger of the shaker attached
/// between mesh nodes, so that the time run drives the station the linear models drive.
///
///   perr = n . (sum w_i p_i - p_B),  n = R_B n_B,
///
/// its first and second time derivatives exact (n turns with B), and its force G^T lambda:
/// lambda w_i n at each p_i, -lambda n on B at the point coincident with A (which carries
/// the torque of n's turn, as Simbody's PointInPlane does).

#include <Simbody.h>

#include <vector>

#include "sim/model/model.hpp"

namespace mmv {

/// Adds the constraint to `matter` (Closure c: !to_ground, one direction, points_a set);
/// `at` (realized to Position) gives the direction in B's frame.
void addWeightedClosure(SimTK::SimbodyMatterSubsystem& matter, const Closure& c, const SimTK::State& at);

}  // namespace mmv

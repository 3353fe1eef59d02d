#pragma once
/// A point force on the article for stiffness computations.

#include <Simbody.h>

namespace mmv {

/// A force held constant in the world frame, at a station of a body (index into
/// Model::getBodies()): used for the stiffness of closure (constraint) forces.
struct PointForce {
  int body = -1;
  SimTK::Vec3 station_B;  ///< m.
  SimTK::Vec3 force_W;    ///< N.
};

}  // namespace mmv

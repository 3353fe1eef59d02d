#include "sim/model/rotation_spring.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mmv {
namespace {

/// The exact rotation vector of the gimbal's x-y-z body-fixed rotation.
SimTK::Vec3 exactRotationVector(const SimTK::Vec3& q) {
  const SimTK::Rotation R(SimTK::BodyRotationSequence, q[0], SimTK::XAxis, q[1], SimTK::YAxis, q[2], SimTK::ZAxis);
  const SimTK::Vec4 aa = R.convertRotationToAngleAxis();
  return aa[0] * SimTK::Vec3(aa[1], aa[2], aa[3]);
}

// psi is the relative rotation's rotation vector to second order: its error falls as
// the cube of the angles (8 times per halving), and it is exact for one angle alone.
TEST(RotationSpring, IsTheRotationVectorToSecondOrder) {
  const SimTK::Vec3 dir(0.7, -0.4, 0.9);
  double previous = 0;
  for (double t : {0.08, 0.04, 0.02, 0.01}) {
    const double err = (rotationVector(t * dir) - exactRotationVector(t * dir)).norm();
    if (previous > 0) EXPECT_NEAR(previous / err, 8.0, 0.3) << t;
    previous = err;
    // The angles themselves miss it at second order: what springs on them got wrong.
    EXPECT_GT((t * dir - exactRotationVector(t * dir)).norm(), 10 * err) << t;
  }
  for (int axis = 0; axis < 3; ++axis) {
    SimTK::Vec3 q(0);
    q[axis] = 0.3;
    EXPECT_LT((rotationVector(q) - exactRotationVector(q)).norm(), 1e-15);
  }
}

// The force is minus the energy's gradient and the Hessian the force's Jacobian (central
// differences), at angles where every term is alive.
TEST(RotationSpring, ForceAndHessianAreTheEnergysDerivatives) {
  const SimTK::Vec3 k(3.0, 7.0, 11.0), q(0.05, -0.08, 0.12);
  const double h = 1e-6;
  const SimTK::Vec3 f = rotationSpringForce(q, k);
  const SimTK::Mat33 H = rotationSpringHessian(q, k);
  for (int j = 0; j < 3; ++j) {
    SimTK::Vec3 qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    EXPECT_NEAR(-(rotationSpringEnergy(qp, k) - rotationSpringEnergy(qm, k)) / (2 * h), f[j], 1e-8) << j;
    const SimTK::Vec3 df = -(rotationSpringForce(qp, k) - rotationSpringForce(qm, k)) / (2 * h);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(df[i], H(i, j), 1e-7) << i << "," << j;
  }
  EXPECT_NEAR(H(0, 1), H(1, 0), 1e-15);
  // Bent in the plane alone (a = b = 0), the springs couple twist and out-of-plane
  // bending by c (k_x - k_y + k_z) / 2 and nothing else.
  const SimTK::Mat33 Hc = rotationSpringHessian(SimTK::Vec3(0, 0, 0.1), k);
  EXPECT_NEAR(Hc(0, 1), 0.1 * (3.0 - 7.0 + 11.0) / 2, 1e-12);
  EXPECT_NEAR(Hc(0, 2), 0.0, 1e-15);
  EXPECT_NEAR(Hc(1, 2), 0.0, 1e-15);
  EXPECT_NEAR(Hc(2, 2), 11.0, 1e-12);
}

}  // namespace
}  // namespace mmv

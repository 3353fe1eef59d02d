#include "sim/model/rotation_spring.hpp"

namespace mmv {

namespace {

/// d psi / dq: row i is psi_i's gradient.
SimTK::Mat33 jacobian(const SimTK::Vec3& q) {
  const double a = q[0], b = q[1], c = q[2];
  return SimTK::Mat33(1, 0.5 * c, 0.5 * b,     //
                      -0.5 * c, 1, -0.5 * a,   //
                      0.5 * b, 0.5 * a, 1);
}

}  // namespace

SimTK::Vec3 rotationVector(const SimTK::Vec3& q) {
  const double a = q[0], b = q[1], c = q[2];
  return {a + 0.5 * b * c, b - 0.5 * a * c, c + 0.5 * a * b};
}

double rotationSpringEnergy(const SimTK::Vec3& q, const SimTK::Vec3& k) {
  const SimTK::Vec3 p = rotationVector(q);
  return 0.5 * (k[0] * p[0] * p[0] + k[1] * p[1] * p[1] + k[2] * p[2] * p[2]);
}

SimTK::Vec3 rotationSpringForce(const SimTK::Vec3& q, const SimTK::Vec3& k) {
  const SimTK::Vec3 p = rotationVector(q);
  const SimTK::Vec3 kp(k[0] * p[0], k[1] * p[1], k[2] * p[2]);
  return -(~jacobian(q) * kp);
}

SimTK::Mat33 rotationSpringHessian(const SimTK::Vec3& q, const SimTK::Vec3& k) {
  const SimTK::Mat33 J = jacobian(q);
  SimTK::Mat33 H = ~J * SimTK::Mat33(k[0], 0, 0, 0, k[1], 0, 0, 0, k[2]) * J;
  const SimTK::Vec3 p = rotationVector(q);
  // psi_x = a + b c / 2: d2/db dc = 1/2; psi_y = b - a c / 2: d2/da dc = -1/2;
  // psi_z = c + a b / 2: d2/da db = 1/2.
  const double bc = 0.5 * k[0] * p[0], ac = -0.5 * k[1] * p[1], ab = 0.5 * k[2] * p[2];
  H(1, 2) += bc;
  H(2, 1) += bc;
  H(0, 2) += ac;
  H(2, 0) += ac;
  H(0, 1) += ab;
  H(1, 0) += ab;
  return H;
}

}  // namespace mmv

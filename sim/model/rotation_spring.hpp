#pragma once
/// The elastic law of a spatial hinge: a gimbal whose three body-fixed angles
/// q = (a, b, c) turn about x (twist), then y (out-of-plane bending), then z (in-plane
/// bending). Its springs act on the relative rotation's rotation vector, not on the
/// angles: energy V = 1/2 sum_i k_i psi_i^2 with, to second order (Baker-Campbell-
/// Hausdorff of exp(a X) exp(b Y) exp(c Z)),
///     psi = (a + b c / 2,  b - a c / 2,  c + a b / 2).
/// Why: the rotation vector is the same seen from either piece (the axis of a rotation
/// is its own), so for a rod bent at a uniform rate kappa each hinge carries h kappa
/// exactly, and the discrete rod converges at second order to the continuum whatever
/// its preload. Springs on the angles themselves carry a spurious a b c (k_x - k_y +
/// k_z) / 2 per hinge: under gravity's in-plane bending c0 = kappa0 h it couples twist
/// and out-of-plane bending by O(h) summed over the link, and the spatial article's
/// torsion-coupled modes converged at first order (docs/spatial.md). psi's third-order
/// terms change V by O(k q^4), which sums to O(h^2).
/// Units: rad, N*m/rad, N*m.

#include <Simbody.h>

#include <array>

namespace mmv {

struct RotationSpring {
  SimTK::MobilizedBodyIndex mobod;  ///< the gimbal.
  std::array<int, 3> coords{};      ///< model coordinates of a, b, c (mobilizer q 0, 1, 2).
  SimTK::Vec3 k;                    ///< stiffness about x, y, z (N*m/rad).
};

/// psi(q), the second-order rotation vector above.
SimTK::Vec3 rotationVector(const SimTK::Vec3& q);
/// V(q) = 1/2 sum k_i psi_i^2 (J).
double rotationSpringEnergy(const SimTK::Vec3& q, const SimTK::Vec3& k);
/// The generalized forces -dV/dq on a, b, c (N*m).
SimTK::Vec3 rotationSpringForce(const SimTK::Vec3& q, const SimTK::Vec3& k);
/// d^2 V / dq^2: J^T diag(k) J + sum_i k_i psi_i d^2 psi_i / dq^2 (N*m/rad); at q with
/// a = b = 0 the diagonal is k and the only coupling is a-b, c (k_x - k_y + k_z) / 2.
SimTK::Mat33 rotationSpringHessian(const SimTK::Vec3& q, const SimTK::Vec3& k);

}  // namespace mmv

#pragma once
/// How a flexible link becomes rigid bodies and rotational springs.
///
/// Discretisation (finite-segment / midpoint-hinge model). A link of length L with N
/// segments is cut into N elements of length h = L/N. Each element's bending
/// flexibility is lumped into one rotational spring at the element's midpoint with
///
///     k = E*I / h   (N*m/rad),
///
/// so the spring's energy k*dtheta^2/2 equals the element's bending energy
/// E*I*kappa^2*h/2 for the mean curvature kappa = dtheta/h (midpoint rule). Between
/// the springs the link is rigid, and the pieces carry the link's distributed mass
/// exactly (mass rho*A*l, centre at the piece's middle, inertia m*l^2/12 about it).
/// The result is N+1 rigid pieces: a half element at the root, N-1 whole elements
/// and a half element at the tip, joined by N hinges at x = (k - 1/2) h.
///
/// For Euler-Bernoulli bending the frequencies and static deflections converge as
/// O(h^2) = O(1/N^2) (tests/article/flexible_link_test.cpp shows the observed order).
/// Rotary inertia of the cross-section (Rayleigh beam) is left out, as in
/// Euler-Bernoulli theory. A rigid link is one piece of length L.

#include <vector>

namespace mmv {

struct LinkPiece {
  double x_start = 0;  ///< m, along the link from its root.
  double length = 0;   ///< m.
  double mass = 0;     ///< kg.
  double inertia_zz_about_com = 0;  ///< kg*m^2, m*l^2/12.
};

struct LinkDiscretization {
  std::vector<LinkPiece> pieces;          ///< root to tip.
  std::vector<double> hinge_x;            ///< m, hinge k joins pieces k and k+1.
  std::vector<double> hinge_stiffness;    ///< N*m/rad, E*I/h for every hinge.
};

/// Splits a link into pieces and hinges. `segments` >= 1; `rigid` gives one piece
/// and no hinge. All inputs in SI and > 0 (checked by the scene reader).
LinkDiscretization discretizeLink(double length, double mass_per_length, double bending_stiffness,
                                  int segments, bool rigid);

}  // namespace mmv

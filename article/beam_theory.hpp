#pragma once
/// Closed-form Euler-Bernoulli results used as references beside computed values.

#include <functional>
#include <vector>

namespace mmv {

/// First `count` positive roots beta*L of the clamped-free (cantilever) frequency
/// equation with a tip point mass ratio mu = M_tip / (rho*A*L) >= 0:
///   1 + cos(bL) cosh(bL) + mu*bL*(cos(bL) sinh(bL) - sin(bL) cosh(bL)) = 0.
/// mu = 0 gives 1.87510, 4.69409, 7.85476, ...
std::vector<double> cantileverTipMassRoots(double mu, int count);

enum class BeamEnd { Clamped, Pinned, Free };

/// First `count` positive roots lambda = beta*L of a uniform Euler-Bernoulli beam with
/// the given root and tip conditions and, at the tip, a point mass ratio
/// mu = M/(rho A L) and a rotary inertia ratio j = J/(rho A L^3). With
/// w = A cos(l x) + B sin(l x) + C cosh(l x) + D sinh(l x) (x = s/L) the conditions are
///   clamped: w = w' = 0;  pinned: w = 0, w'' = l^4 j w';  free: w'' = l^4 j w',
///   w''' = -l^4 mu w  (tip terms only at the tip; the root carries no mass),
/// and the roots are the zeros of the 4x4 determinant (rows at the tip scaled by
/// 1/cosh l). Clamped-free with mu = j = 0 gives 1.87510, 4.69409, ...; rigid-body
/// roots at lambda = 0 (pinned-free, free-free) are not returned.
std::vector<double> beamRoots(BeamEnd root, BeamEnd tip, double mu, double j, int count);

/// First `count` positive roots beta of free torsion of a uniform shaft (torsion
/// constant J, polar moment of area I_p) carrying at its tip a disk of polar inertia
/// J_d, with r = J_d / (rho I_p L) >= 0 and omega = (beta / L) sqrt(G J / (rho I_p)).
/// With theta = cos or sin(beta x / L) and G J theta'(L) = J_d omega^2 theta(L):
///   root clamped: cos(beta) - r beta sin(beta) = 0  (r = 0: (2k - 1) pi / 2);
///   root free:    sin(beta) + r beta cos(beta) = 0  (r = 0: k pi; the rigid root 0 left out).
/// `root` is Clamped or Free (a pinned root holds torsion: it is Clamped here).
std::vector<double> torsionRoots(BeamEnd root, double r, int count);

/// Natural frequency in Hz of a torsion root: beta / (2 pi L) sqrt(G J / (rho I_p)).
double torsionFrequencyHz(double beta, double length, double torsion_stiffness, double polar_inertia_per_length);

/// Natural frequency in Hz of a uniform Euler-Bernoulli beam for a root beta*L:
///   f = (beta L)^2 / (2 pi L^2) * sqrt(E I / (rho A)).
double beamFrequencyHz(double beta_l, double length, double bending_stiffness,
                       double mass_per_length);

/// Positive roots of f on (lo, hi], found by scanning with `step` for sign changes
/// and refining each by bisection to machine precision. At most `count` roots.
std::vector<double> findRoots(const std::function<double(double)>& f, double lo, double hi,
                              double step, int count);

/// Static tip deflection in m of a horizontal cantilever under its own weight
/// w = rho*A*g (N/m): w L^4 / (8 E I).
double cantileverSelfWeightTipDeflection(double w, double length, double bending_stiffness);
/// Static tip deflection in m of a cantilever under a tip load P (N): P L^3 / (3 E I).
double cantileverTipLoadDeflection(double p, double length, double bending_stiffness);

}  // namespace mmv

#pragma once
/// The spatial article (docs/spatial.md): what each mode bends, and whether a test that
/// excites the article in its plane stays planar.
///
/// Classification: the shape's strain energy split over its hinge coordinates' axes
/// (Model's HingeAxis: in-plane bending, out-of-plane bending, torsion; a servo joint's
/// spring counts in-plane). A family with at least kFamilyShare of it names the mode;
/// otherwise the mode is "mixed"; a shape that strains nothing is "rigid".
///
/// Planarity report, over the solved modes in the 0.1-50 Hz band of the report's tests:
///  - every mode in the band that is not in-plane, with the nearest in-plane mode and
///    their separation (a test that resolves only a few per cent cannot tell them apart);
///  - the response out of the article's plane (along its normal n, the torquers' axis)
///    against the response in it, at every link tip under each in-plane excitation: base
///    translation x and y (a shaker under the base) and each held coordinate (a torquer
///    slew, the table, a gimbal axis). With equal modal damping zeta the peak resonant
///    response of mode i at point p is |Gamma_i| |d_ip| / (2 zeta omega_i^2), Gamma_i the
///    mode's participation in the excitation (phi_i^T M r for the excitation's influence
///    r) and d_ip the point's motion in the mode, so
///        ratio = max_i |Gamma_i n.d_ip| / omega_i^2  /  max_i |Gamma_i (I - n n^T) d_ip| / omega_i^2
///    (zeta cancels). A symmetric planar article gives 0 to round-off (the families do
///    not couple); an asymmetry shows up here first.

#include <optional>
#include <Eigen/Dense>
#include <Simbody.h>

#include <string>
#include <vector>

#include "sim/model/model.hpp"
#include "sim/modes/modal.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

struct ModeFamily {
  double in_plane = 0, out_of_plane = 0, torsion = 0;  ///< strain energy shares, 0..1.
  std::string label;  ///< in-plane, out-of-plane, torsion, mixed, rigid.
};

inline constexpr double kFamilyShare = 0.8;
/// Ratios below this are round-off of a decoupled response (reported as decoupled).
inline constexpr double kDecoupledRatio = 1e-9;

ModeFamily classifyMode(const Model& model, const std::vector<int>& dofs, const Eigen::VectorXd& phi);

/// Within every cluster of solved modes whose omega^2 agree to `tolerance` (relative),
/// any M-orthonormal basis is a set of modes: a round rod's in-plane and out-of-plane
/// bending pair comes out of the eigensolver in an arbitrary mix of the two. Rotates
/// each cluster's shapes to the basis that diagonalizes the families' weighted strain
/// energy (in-plane 1, out-of-plane 2, torsion 3), so each comes out in one family when
/// the families are what is degenerate.
void separateDegenerateFamilies(const Model& model, const std::vector<int>& dofs, ModalSolution& modes,
                                double tolerance = 1e-9);

struct PlanarityMode {
  ModeNumber number;  ///< as in the modes table.
  double frequency_hz = 0;
  ModeFamily family;
  std::optional<ModeNumber> nearest_in_plane;  ///< none if the band has no in-plane mode.
  double nearest_hz = 0;
  double separation_pct = 0;  ///< 100 (f - f_nearest) / f_nearest.
};

struct PlanarityResponse {
  std::string excitation;  ///< "base x", "base y", or a held coordinate ("joint1", "gimbal.roll").
  std::string point;       ///< a link tip.
  double ratio = 0;        ///< out of the plane / in it (above).
  bool decoupled = false;  ///< ratio below kDecoupledRatio.
  ModeNumber out_mode, in_mode;  ///< the modes that give the two peaks.
};

struct PlanarityReport {
  double band_low_hz = 0.1, band_high_hz = 50;
  double solved_up_to_hz = 0;  ///< the highest mode solved: the band is covered when above band_high_hz.
  bool covers_band = false;
  int in_plane_in_band = 0;
  std::vector<PlanarityMode> others;  ///< out-of-plane, torsion and mixed modes in the band.
  std::vector<PlanarityResponse> responses;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< the article plane's normal, world.
};

/// `eqs` realized to Position; `modes` over `dofs` (the model's DOFs).
PlanarityReport planarityReport(const Model& model, const SimTK::State& eqs, const std::vector<int>& dofs,
                                const ModalSolution& modes);

}  // namespace mmv

#pragma once
/// Component mode synthesis: the assembled article's modes predicted from a few modes
/// of each link, compared with the full model's system modes.
///
/// The synthesis is a Rayleigh-Ritz reduction of the full linearized model at the
/// actual (deflected, preloaded) configuration: every flexible link's hinge angles are
/// restricted to the span of its component basis, joint coordinates that are degrees
/// of freedom are kept, T is the block matrix of those bases, and
///
///     (Z_r^T T^T K T Z_r) psi = omega^2 (Z_r^T T^T M T Z_r) psi,   phi = T Z_r psi,
///
/// with Z_r the null space of the closures' Jacobian G T. Being a Ritz reduction,
/// its frequencies bound the full model's from above, and it is exact when the bases
/// span each link's hinge space. Bases:
///  - assumed modes: the first k component modes of each link under one boundary
///    condition and tip-mass rule (sim/modes/components.hpp);
///  - Craig-Bampton: per link, the static constraint modes of its tip interface
///    (unit tip deflection and unit tip rotation, minimum strain energy) when a joint
///    or a loop closure sits at its tip, plus its first k fixed-interface modes (root and tip interface
///    clamped), from the link alone without tip masses (the outboard parts are other
///    components).
///
/// Shapes are compared by the MAC of their translations at every named point,
/// MAC(a, b) = (a.b)^2 / ((a.a)(b.b)).

#include <optional>
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "sim/modes/components.hpp"
#include "sim/modes/modal.hpp"
#include "sim/scene/scene.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

/// MAC between the columns of A (rows of the result) and of B (columns).
Eigen::MatrixXd modalAssuranceCriterion(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// Craig-Bampton basis of a component with mass M, stiffness K and interface
/// displacements y = C u (C: nb x n): [Psi | Phi_k], Psi = the minimum-energy shapes
/// with C Psi = I (from the KKT system [K C^T; C 0]), Phi_k the first k modes of
/// (K, M) with C u = 0. When C selects DOFs this is the classical constraint-mode and
/// fixed-interface-mode basis.
Eigen::MatrixXd craigBamptonBasis(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& C, int k);

/// Modes of (M, K) restricted to the columns of T and to G u = 0 (G may be empty),
/// returned over the full coordinates (phi = T Z_r psi).
ModalSolution ritzModes(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const Eigen::MatrixXd& T,
                        const Eigen::MatrixXd& G);

enum class CmsMethod { AssumedModes, CraigBampton };
const char* cmsMethodName(CmsMethod m);

struct SynthesisOptions {
  CmsMethod method = CmsMethod::AssumedModes;
  ComponentOptions component;  ///< boundary condition and tip rule (assumed modes).
  int modes_per_link = 4;
  int compare_modes = 8;        ///< system modes compared.
  double frequency_tolerance = 0.01;  ///< verdict: "predicted" within this relative error
  double mac_threshold = 0.9;         ///< ... and with at least this MAC.
};

struct SynthesisRow {
  ModeNumber mode;  ///< the full model's mode.
  double full_hz = 0, synth_hz = 0;
  ModeNumber synth_mode;  ///< the synthesized mode that matches best (by MAC).
  double relative_error = 0;
  double mac = 0;
  std::string verdict;  ///< predicted, shifted, missed.
  std::string dominant_link;  ///< by strain energy in the full model.
  std::string family;         ///< spatial model: the full mode's family (planarity.hpp); else empty.
};

struct SynthesisResult {
  std::string method;  ///< e.g. "assumed modes, clamped-free, tip: torquer, 4 per link".
  int full_dofs = 0, reduced_dofs = 0;
  std::vector<SynthesisRow> rows;
  Eigen::VectorXd full_hz, synth_hz;  ///< first compare_modes of each.
  Eigen::MatrixXd mac;  ///< synthesized (rows) x full (columns), first compare_modes.
  Eigen::MatrixXd full_point_shapes;  ///< full model's shapes at the named points (P phi), compared modes.
};

/// Throws NumericalError if a solve fails.
SynthesisResult synthesize(const ArticleScene& scene, const SynthesisOptions& options);

/// Verdict for a matched pair: "predicted" (MAC >= threshold, |error| <= tolerance),
/// "shifted" (MAC >= threshold, larger error) or "missed" (no shape like it).
std::string synthesisVerdict(double relative_error, double mac, const SynthesisOptions& o);

}  // namespace mmv

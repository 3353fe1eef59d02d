#pragma once
/// Test-analysis models (TAM): the model reduced to the degrees of freedom a sensor set
/// measures, and the orthogonality checks a test-readiness review makes with it
/// (NASA-STD-5002, MIL-HDBK-340A: self-orthogonality of the analysis modes under the
/// TAM mass, off-diagonal <= 0.1; cross-orthogonality of the TAM's modes against the full
/// model's, diagonal >= 0.9 and off-diagonal <= 0.1).
///
/// The sensors measure translations that are combinations of the model's coordinates
/// (hinge angles), not coordinates themselves: the coordinates are first changed to
/// x = [u_a; q_o] (the a sensor readings and the n - a coordinates the sensors leave
/// least determined, chosen by a column-pivoted QR of the sensor rows P), so the
/// reductions are the textbook ones on the a-set u_a and the o-set q_o:
///   Guyan (static): q_o = -K_oo^-1 K_oa u_a;
///   IRS (improved reduced system, O'Callahan 1989): Guyan plus the o-set's inertia
///     at the Guyan model's frequencies, T = T_G + S M T_G M_G^-1 K_G, S = [0 0; 0 K_oo^-1];
///   SEREP (system equivalent reduction expansion, O'Callahan, Avitabile, Riemer 1989):
///     T = Phi (P Phi)^+ over the target modes Phi, exact for them at any sensor set
///     that tells them apart (a >= m, P Phi of rank m).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include "sim/core/mode_number.hpp"

namespace mmv {

enum class TamMethod { Guyan, Irs, Serep };
const char* tamMethodName(TamMethod m);  ///< "guyan", "irs", "serep"
/// "guyan", "irs", "serep" (and "static" for Guyan); false for anything else.
bool parseTamMethod(const std::string& name, TamMethod& out);

/// The criteria (NASA-STD-5002 section 4.2.1, MIL-HDBK-340A).
inline constexpr double kTamDiagonalMin = 0.9, kTamOffDiagonalMax = 0.1;

struct TamInput {
  Eigen::MatrixXd M, K;    ///< n x n over the model's admissible coordinates (symmetric; M positive definite)
  Eigen::MatrixXd P;       ///< a x n: each sensor direction's reading per unit coordinate
  Eigen::MatrixXd phi;     ///< n x m: the target modes, mass-normalised (phi^T M phi = I)
  Eigen::VectorXd omega2;  ///< m: their eigenvalues, rad^2/s^2
};

/// One target mode's checks.
struct TamModeCheck {
  ModeNumber tam_mode;              ///< the TAM mode it pairs with (by the largest |cross-orthogonality|)
  double tam_frequency_hz = 0;      ///< that TAM mode's frequency
  double frequency_error = 0;       ///< tam / full - 1
  double self_diagonal = 0;         ///< phi_a^T M_tam phi_a, unnormalised (1: the TAM carries the mode's whole mass)
  double self_off_diagonal = 0;     ///< the largest |normalised off-diagonal| of its row
  double cross_diagonal = 0;        ///< |cross-orthogonality| with its TAM mode
  double cross_off_diagonal = 0;    ///< the largest |cross-orthogonality| of its TAM mode with another target
  bool pass = false;
  std::string reason;               ///< the first criterion it fails (empty: passes)
};

struct TamResult {
  TamMethod method = TamMethod::Guyan;
  int sensors = 0, coordinates = 0;
  Eigen::MatrixXd T;              ///< n x a: coordinates = T * readings
  Eigen::MatrixXd M_tam, K_tam;   ///< a x a
  Eigen::VectorXd tam_omega2;     ///< the TAM's own eigenvalues (on the range of M_tam), ascending
  Eigen::MatrixXd tam_shapes;     ///< a x r, mass-normalised under M_tam
  Eigen::MatrixXd self;           ///< m x m: normalised phi_a^T M_tam phi_a
  Eigen::MatrixXd cross;          ///< r x m: TAM modes (rows) against the targets at the sensors (columns)
  std::vector<TamModeCheck> modes;  ///< one per target
  bool pass = false;              ///< every target passes
};

/// Builds the TAM and its checks. Throws NumericalError naming the cause: dependent
/// sensor directions (P of rank < a), an o-set stiffness that is singular (a motion the
/// sensors do not see and nothing resists), targets the sensors cannot tell apart
/// (SEREP); OptionError (--tam) for fewer sensor directions than targets (SEREP).
TamResult buildTam(const TamInput& in, TamMethod method);

}  // namespace mmv

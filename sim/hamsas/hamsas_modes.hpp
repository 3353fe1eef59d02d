#pragma once
/// HAM-SAS analyses: modes with energy shares and the measured-vs-model table,
/// the 6 x 6 ground-to-optical-table transmissibility, and the actuator-to-sensor model.

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "article/hamsas.hpp"
#include "sim/core/mode_number.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {

struct SpatialMode {
  double frequency_hz = 0;  ///< negative: unstable (sqrt(-omega^2) / 2 pi).
  std::string label;        ///< the body group and direction holding most kinetic energy, e.g. "ot z".
  std::map<std::string, double> kinetic_share;  ///< per body group, and per "group.direction".
  /// Per element group: its share of the elastic strain energy (each >= 0, summing to 1).
  std::map<std::string, double> strain_share;
  /// The work of the elements' preloads (gravity carried through joints and springs: a
  /// pendulum's restoring stiffness, an inverted pendulum's negative one) over the
  /// elastic strain energy: -0.99 where gravity takes back 99 % of what the flex joints
  /// store (an IP tuned low). The mode's net stiffness energy is (1 + this) x elastic.
  double preload_over_elastic = 0;
};

/// One measured feature (docs/sources.md section 3) and the model mode that shows it.
struct FeatureMatch {
  std::string feature;
  double measured_hz = 0;
  double model_hz = 0;  ///< 0 when no mode shows it (e.g. joint modes with ideal joints).
  std::optional<ModeNumber> mode;  ///< the model mode that shows it; none: no mode does.
  double shape_match = 0;  ///< mass-weighted correlation with the feature's shape, 0..1.
  std::string rule;        ///< how the mode was identified.
};

struct HamsasModes {
  HamsasSpec spec;
  SpatialSpec model;
  SpatialLinearization lin;
  ModalSolution solution;
  std::vector<SpatialMode> modes;
  std::vector<FeatureMatch> features;
  double max_relative_residual = 0;  ///< max_i ||K v - w^2 M v|| / (w^2 ||M v||), over the flexible modes.
};

/// Linearizes and solves; identifies the measured features. Throws NumericalError.
HamsasModes analyseHamsas(const HamsasSpec& spec);
/// `h.modes` from `h.solution` (energy shares and labels per mode).
void describeModes(HamsasModes& h);

/// The measured features (docs/sources.md section 3), Hz.
const std::vector<std::pair<std::string, double>>& hamsasMeasuredFeatures();

/// Ground-to-optical-table transmissibility over a frequency grid (Hz): [f][6 x 6].
std::vector<Eigen::MatrixXcd> hamsasTransmissibility(const HamsasModes& h, const std::vector<double>& freqs_hz);

/// The 8 x 8 actuator (force, N) to sensor (relative displacement, m) model, full order.
StateSpace hamsasControlModel(const HamsasModes& h);

/// One value of a varied parameter: the IP frequency and the transmissibility's
/// x and z magnitudes at 1, 3 and 10 Hz (dB), and |T_xx| over `freqs_hz` (dB).
struct HamsasVaryPoint {
  double value = 0;
  double ip_hz = 0;
  double x_at_1hz_db = 0, x_at_3hz_db = 0, x_at_10hz_db = 0, z_at_10hz_db = 0;
  std::vector<double> x_db;
};

/// The isolator with parameter `key` (a HamsasParameter key) set to each value.
/// Throws std::invalid_argument for an unknown key (the message lists the known ones)
/// or a non-physical value.
std::vector<HamsasVaryPoint> varyHamsas(const HamsasSpec& spec, const std::string& key, const std::vector<double>& values,
                                        const std::vector<double>& freqs_hz);

}  // namespace mmv

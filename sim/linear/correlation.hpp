#pragma once
/// Test-analysis correlation: a measured modal test (FRFs, mode shapes, the measurement
/// points' geometry) against the article's model, as `mmvlab correlate` reports it.
///
///  - Points: each measured node is paired with the station of the physical article
///    nearest to it (the deflected equilibrium's centrelines, searched along every
///    link by distance from its root: a station, not a mesh node, so the pairing does
///    not change with the segments per link), when within `pair_distance_m`; or with
///    the point or station the user names for it.
///  - Modes: MAC = |phi_t^H phi_m|^2 / ((phi_t^H phi_t)(phi_m^H phi_m)) over the paired
///    nodes' translations (x, y, z; the planar model's z is 0, so out-of-plane motion in
///    a test shape lowers its MAC), complex test shapes as they are. Test and model modes
///    are paired greedily from the largest MAC down, each at most once, and only at or
///    above `mac_threshold` and within the frequency window |f_model / f_test - 1| <=
///    `max_frequency_error` (a 167 Hz test mode is not a 62.7 kHz model mode, whatever
///    the MAC over a few points says; a high-MAC candidate outside the window is named in
///    a note); the frequency error of a pair is (f_model - f_test) / f_test. A MAC
///    with a shape that is zero over the paired translations is undefined (NaN in
///    `mac`, "undefined" and null in the outputs), never 0.
///    Model modes in the test's band that pair with no test mode are the ones the test
///    did not see; test modes that pair with none are the ones the model does not have.
///  - FRFs: each measured function is modelled with the same output (the response node's
///    station, direction and quantity: displacement, velocity, acceleration) and input
///    (acceleration in the denominator: the table's acceleration along the reference
///    direction; force: a force at the reference node's station), and compared by
///    FRAC = |sum conj(H_t) H_m|^2 / (sum |H_t|^2 sum |H_m|^2) over the measured
///    frequencies (1: the same shape of response, level and phase included), judged
///    against kFracThreshold: "consistent" at or above it, "differs" below (FRAC falls
///    fast with a small frequency shift at a lightly damped peak: a model within 1 % in
///    frequency can read 0.5, so a low FRAC asks for the Bode overlay, and says so).
///  - Notes: every node that pairs with no station, that has no geometry (a mode shape's
///    node the file never placed), or that shares its station with another node.
///
/// Frames: the measured geometry is in the scene's world frame (m, after the file's
/// units), as our UFF writer puts it. Directions 1..3 are +x, +y, +z, negative ones the
/// opposite; z and rotations (4..6) are outside the planar model and are reported as such.
#include <array>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/linear/state_space.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

struct MeasuredNode {
  int label = 0;
  std::array<double, 3> xyz{};  ///< m, the scene's world frame.
};

struct MeasuredMode {
  int number = 0;
  double frequency_hz = 0, damping_ratio = 0;
  std::vector<int> nodes;
  std::vector<std::array<std::complex<double>, 3>> shape;  ///< per node: x, y, z translations.
};

struct MeasuredFrf {
  std::string id;    ///< the function's description (UFF 58 ID line 1).
  int line = 0;      ///< where it starts in its file.
  int function_type = 4;  ///< 4 FRF, 5 transmissibility (others are not frequency responses).
  int response_node = 0, response_direction = 0, reference_node = 0, reference_direction = 0;
  int ordinate_type = 12;     ///< 8 displacement, 11 velocity, 12 acceleration.
  int denominator_type = 13;  ///< 12 acceleration (of the base), 13 force.
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> values;  ///< SI.
};

struct MeasuredSet {
  std::string source;
  std::vector<MeasuredNode> nodes;
  std::vector<MeasuredMode> modes;
  std::vector<MeasuredFrf> frfs;
};

/// FRAC at or above this: the measured and modelled responses are consistent.
inline constexpr double kFracThreshold = 0.9;

struct CorrelateOptions {
  double pair_distance_m = 0.05;   ///< a node farther than this from the article is not paired.
  std::vector<std::pair<int, std::string>> named_pairs;  ///< node -> point or station, by the user.
  int model_modes = 20;            ///< model modes compared.
  double mac_threshold = 0.7;      ///< pairs below it are not pairs.
  double max_frequency_error = 0.3; ///< |f_model / f_test - 1| above it: not a pair, whatever the MAC.
  DampingSpec damping;             ///< the model's damping (FRFs and its modes' ratios).
};

struct NodePairing {
  int node = 0;
  std::array<double, 3> xyz{};
  std::string station;   ///< empty: not paired.
  double distance_m = 0; ///< from the node to its station at the equilibrium.
  bool by_name = false;  ///< named by the user.
  bool by_number = false;  ///< its number is a station's in mmvlab's test geometry (placement's nodes), confirmed by position
};

/// The station a test-geometry node number names (PlacementCandidate::node: link position
/// x 100000 + mm from the root), or "" when it names none of `article`'s.
std::string stationOfNode(const ArticleSpec& article, int node);

struct ModePair {
  int test = -1, model = -1;  ///< indices into the test and model mode lists.
  double mac = 0;
};

struct FrfCorrelation {
  int index = 0;           ///< 0-based, in the file's order.
  std::string id, output, input;  ///< the model's output and input (frf's names), empty when not modelled.
  std::string skipped;     ///< why it was not modelled (empty: it was).
  double frac = 0;
  double test_peak_hz = 0, model_peak_hz = 0;  ///< the largest |H| of each on the measured frequencies.
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> test, model;  ///< on the measured frequencies.
};

struct CorrelationResult {
  std::vector<NodePairing> nodes;
  std::vector<MeasuredMode> test_modes;
  std::vector<ModeInfo> model_modes;   ///< with their damping ratios
  bool model_damped = false;
  std::string damping_model;
  Eigen::MatrixXd mac;                 ///< test x model; NaN where undefined (a shape zero at the paired points).
  int shape_dofs = 0;                  ///< paired node translations the MAC is taken over.
  std::vector<ModePair> pairs;
  double band_min_hz = 0, band_max_hz = 0;  ///< the test's band: its FRFs' range, else 0 to 1.1x its top mode.
  std::vector<int> model_not_seen;     ///< model modes in the band without a test mode.
  std::vector<int> test_not_predicted; ///< test modes without a model mode.
  std::vector<FrfCorrelation> frfs;
  std::vector<std::string> warnings;
  std::vector<std::string> notes;      ///< nodes left out or sharing a station; candidates outside the window.
};

/// MAC of two shapes over the same DOFs; NaN (undefined) when either is zero.
double modalAssurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b);
/// FRAC of two responses over the same frequencies; 0 when either is zero.
double frequencyResponseAssurance(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b);
/// Pairs rows with columns of a MAC matrix, largest first, each once, at or above
/// threshold, and only where `allowed` (same size; empty: everywhere). NaN never pairs.
std::vector<ModePair> pairByMac(const Eigen::MatrixXd& mac, double threshold,
                                const Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>& allowed = {});

/// The whole correlation (see above). Throws SceneError when a named pair names an
/// unknown node, point or station, or when no measured node pairs with the article;
/// NumericalError as the model's analyses do.
CorrelationResult correlate(const ArticleScene& scene, const MeasuredSet& test, const CorrelateOptions& options);

}  // namespace mmv

#pragma once
/// The extra shaker in a pre-test analysis (`place-sensors` on a scene with `shaker:`;
/// facility/shaker.hpp): where to attach it, what its armature does to the article, and
/// whether the chosen sensors see every target mode above their resolution without
/// leaving their range or the shaker its stroke.
///
/// Ranking. Every candidate direction of the placement (a station and an axis) is an
/// attachment candidate. Its driving-point residue for target mode r is u_r(d)^2, the
/// mass-normalised shape's component along the direction squared (the response at the
/// driving point at resonance is F u_r(d)^2 / (2 zeta_r omega_r^2): the residue is how
/// much of mode r the point both feeds and sees). The armature mass m_a shifts mode r by
/// -m_a u_r(d)^2 / 2 to first order; a candidate shifting any target by more than
/// kArmatureShiftLimit "loads" the article (it tests a different one) and is ranked
/// after every one that does not. Normalised by the best residue for the same mode among
/// the candidates that do not load (all, when every one does), the score of a candidate
/// is the smallest over the target modes: the fraction of the best usable excitation
/// that its worst-fed mode gets (1: every mode as well fed as anywhere usable; 0: a node
/// of some mode). `shaker.at: auto` attaches at the first of the ranking.
///
/// Levels. The linear model of `frf` (the scene's damping, else 1 % modal; the armature's
/// mass moving with the driving point along the direction: the stinger is stiff along
/// its axis and free across it) with the shaker's force as the input and
/// the absolute acceleration of every chosen sensor direction as outputs:
///  - sine dwell at each target mode's frequency (the loaded model's mode that follows
///    it, by MAC): the force is the shaker's limit, lowered where the driving point's
///    displacement would pass the stroke or a sensor its range; the signal-to-noise ratio
///    is 20 log10(|a| / resolution) at the sensor that sees the mode most;
///  - random, a flat force spectrum over the band at RMS force_limit / crest_factor:
///    each sensor's RMS by integrating |H|^2 G_F over the band (the grid resolves every
///    resonance), 3 sigma against its range, 3 sigma of the driving point against the
///    stroke (the force lowered to fit both); per mode, the response spectrum at its
///    frequency over the quantization noise's, q^2 / (6 fs) for resolution q sampled at
///    fs (the scene's sample rate).
/// Every sensor is the report's accelerometer (facility/sensors.hpp: 0.001 g, +-5 g).

#include <array>
#include <string>
#include <vector>

#include "sim/core/mode_number.hpp"
#include "sim/linear/state_space.hpp"
#include "sim/linear/strength_levels.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// The largest first-order frequency shift (fraction) the armature may make on a target
/// mode for its attachment to rank among those that leave the article as it is.
inline constexpr double kArmatureShiftLimit = 0.02;
/// A mode is seen when its best sensor's signal-to-noise ratio reaches this (dB).
inline constexpr double kSeenSnrDb = 20;
/// A target mode of the loaded article damped less than this has no bounded resonance:
/// runExciter refuses it (SceneError) rather than report round-off as levels.
inline constexpr double kLeastDampingRatio = 1e-6;

struct ExciterCandidate {
  int direction = 0;        ///< row of PlacementStudy::directions
  std::string station, axis;
  std::array<double, 3> world{};
  int node = 0;
  double score = 0;         ///< the weakest mode's normalised driving-point residue, 0..1
  ModeNumber weakest{1};    ///< that mode
  double max_shift = 0;     ///< the armature's largest first-order shift over the targets (negative: down)
  bool loads = false;       ///< |max_shift| > kArmatureShiftLimit
};

struct ExciterStudy {
  facility::ShakerSpec hardware;
  std::string at, axis;                ///< the attachment: station, and its axis name when a candidate's
  std::array<double, 3> direction{};   ///< unit, world
  bool chosen = false;                 ///< `auto`: the first of the ranking
  std::vector<ExciterCandidate> ranking;  ///< every candidate, best first
  std::string damping;                 ///< the model's damping, as the report states it
  double resolution = 0, range = 0;    ///< m/s^2, each sensor's
  double sample_rate_hz = 0;
  struct Mode {
    ModeNumber mode{1}, loaded_mode{1};
    double frequency_hz = 0, loaded_hz = 0, mac = 0;
    double zeta = 0;                   ///< the loaded mode's damping ratio (diagonal of the modal damping)
    // Sine dwell at loaded_hz.
    double sine_force_n = 0;
    std::string sine_limit;            ///< force, stroke, range, stress or deflection: what set the force
    double sine_acc = 0;               ///< m/s^2 amplitude at the best sensor
    std::string best_channel;          ///< "station axis"
    double sine_snr_db = 0;
    double sine_stroke_m = 0;          ///< the driving point's amplitude at that force
    int channels_seen = 0;             ///< sensors at or above kSeenSnrDb
    LevelStrength strength;            ///< the links' stress and the tips' motion in the dwell
    // Random.
    double random_snr_db = 0;          ///< the best sensor's response spectrum over the noise's, at loaded_hz
    bool seen = false;                 ///< sine_snr_db >= kSeenSnrDb
  };
  std::vector<Mode> modes;
  struct Random {
    double f_min_hz = 0, f_max_hz = 0;
    double rms_force_n = 0;            ///< used: force_limit / crest_factor, lowered to fit
    std::string limit;                 ///< force, stroke, range or "stress (LINK)"
    double rms_acc = 0;                ///< the largest sensor RMS, m/s^2
    std::string rms_channel;
    double stroke_rms_m = 0;           ///< the driving point's RMS displacement
    int grid_points = 0;
  } random;
};

/// A chosen sensor direction: its station, "station axis" and world axis.
struct SensorChannel {
  std::string station, name;
  std::array<double, 3> world{};
};
/// Every measured direction of `study`'s chosen sensors, in the placement's order.
std::vector<SensorChannel> chosenSensorChannels(const PlacementStudy& study);

/// The undamped modes of a linear model's admissible coordinates and each one's damping
/// ratio, the diagonal of the modal damping (psi^T C psi / 2 omega; 0 for a rigid mode).
ModalSolution dampedModes(const LinearModel& lm, std::vector<double>& zeta);

/// The shaker of `scene` (MMV_DEMAND: it has one) against `study`'s targets and chosen
/// sensors. Throws SceneError when a target mode is undamped (below kLeastDampingRatio),
/// NumericalError when the model cannot respond (a singular model).
/// Every level is also held to the links' strength and, with `max_deflection_m` > 0,
/// every tip's motion within it (sim/linear/strength_levels.hpp).
ExciterStudy runExciter(const ArticleScene& scene, const PlacementStudy& study, double max_deflection_m = 0);

/// The ranking of every candidate direction of `study` for a shaker of armature mass
/// `armature_kg` (best first; ties by the candidates' order).
std::vector<ExciterCandidate> rankExciterCandidates(const PlacementStudy& study, double armature_kg);

}  // namespace mmv

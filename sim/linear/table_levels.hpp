#pragma once
/// The base excitation table's own levels in a pre-test analysis (`place-sensors` on a
/// scene whose base is the table): for each target mode, a sine dwell of the table at
/// the mode's frequency, as large as its stroke allows (acceleration amplitude
/// stroke x omega^2), lowered where a chosen sensor would pass its range, along the
/// table's axis that shows the mode best (x in the plane; on the spatial model also z,
/// across it); the absolute acceleration of every chosen sensor direction from the
/// linear model of `frf` (the scene's damping, else 1 % modal), its signal-to-noise
/// ratio against the accelerometer's resolution at the sensor that sees the mode most,
/// and whether the frequency is within the table's servo bandwidth (10 Hz: above it the
/// loop attenuates the motion, and the mode is not counted as seen). Each dwell is also
/// held to the article's strength (docs/strength.md): every flexible link's bending
/// stress amplitude in it (its hinges' moments at the root, the hinges and the tip, the
/// linear model's) added to its static peak stays within its allowable over its factor,
/// and, when the user states one (`--max-deflection`), every tip's motion relative to
/// the table within that limit. Also a random
/// program of the table over its band at the stroke (TableLevels::Random) and each
/// target's signal-to-noise in it.

#include <string>
#include <vector>

#include "facility/table_programs.hpp"
#include "sim/core/mode_number.hpp"
#include "sim/linear/strength_levels.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

struct TableLevels {
  facility::TableSpec table;
  double resolution = 0, range = 0;  ///< m/s^2, each sensor's
  struct Mode {
    ModeNumber mode{1};
    double frequency_hz = 0;
    std::string axis;              ///< the table's axis of the dwell: x or z
    double table_acc = 0;          ///< m/s^2, the table's acceleration amplitude
    double table_amplitude_m = 0;  ///< its displacement amplitude
    std::string limit;             ///< stroke, range, stress (a link's allowable) or deflection: what set it
    LevelStrength strength;  ///< the links' stress and the tips' motion in the dwell
    double acc = 0;                ///< m/s^2, the amplitude at the best sensor
    std::string best_channel;      ///< "station axis"
    double snr_db = 0;             ///< 20 log10(acc / resolution)
    int channels_seen = 0;         ///< sensor directions at or above kSeenSnrDb
    bool within_bandwidth = true;  ///< frequency_hz <= the table's bandwidth
    bool seen = false;             ///< within the bandwidth and snr_db >= kSeenSnrDb
    /// The random program's (below): the best channel's acceleration spectrum at the
    /// mode's frequency over the sensor's noise floor, dB; NaN when the random program
    /// does not reach the mode (above the bandwidth, or no program).
    double random_snr_db = 0;
  };
  std::vector<Mode> modes;
  double max_deflection_m = 0;  ///< the tips' limit the user stated (0: none)
  /// A band-limited random program of the table along x (a flat displacement spectrum,
  /// as `base.motion: {type: random}`), over [f_min, f_max]: from half the lowest target
  /// (at least 0.1 Hz) to the table's bandwidth. Its RMS displacement is the stroke over
  /// kTableCrestFactor, lowered where the crest factor times a sensor's RMS would pass
  /// its range. Absent (program = false) when no target lies within the bandwidth.
  struct Random {
    bool program = false;
    double f_min_hz = 0, f_max_hz = 0;
    double rms_m = 0;         ///< the table's RMS displacement
    std::string limit;        ///< stroke or range
    double rms_acc = 0;       ///< the largest sensor RMS, m/s^2 (absolute acceleration)
    std::string rms_channel;  ///< whose
    int grid_points = 0;
    double noise_psd = 0;     ///< (m/s^2)^2/Hz: resolution^2 / (6 x the scene's sample rate)
  } random;
};

/// A random program's peak over its RMS (Gaussian, clipped at 3 sigma), as the shaker's
/// assumed crest factor.
inline constexpr double kTableCrestFactor = 3;

/// The table's dwell levels for `study`'s targets on its chosen sensors. MMV_DEMAND: the
/// scene's base is the table.
TableLevels runTableLevels(const ArticleScene& scene, const PlacementStudy& study, double max_deflection_m = 0);

}  // namespace mmv

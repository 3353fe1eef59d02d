#pragma once
/// Motion programs of the Base Excitation Table (report: programmable deterministic,
/// random, sine dwell and sine sweep motion; expected like the ACES table: +-15 cm
/// dynamic range, 10 Hz bandwidth, hydraulic position loop; 2.3 kN payload). A
/// program gives the commanded displacement x(t) (m) along one axis with its velocity
/// and acceleration; `checkProgram` enforces the stroke and flags content above the
/// table's bandwidth.

#include <memory>
#include <random>
#include <string>
#include <vector>

namespace mmv::facility {

struct TableSpec {
  double stroke = 0.15;        ///< m, +- about the centre.
  double bandwidth_hz = 10;    ///< Hz, the servo loop's bandwidth.
  double payload_n = 2300;     ///< N, article + sensors + actuators + gimbal.
};

class TableProgram {
 public:
  virtual ~TableProgram() = default;
  virtual double position(double t) const = 0;      ///< m
  virtual double velocity(double t) const = 0;      ///< m/s
  virtual double acceleration(double t) const = 0;  ///< m/s^2
  virtual double duration() const = 0;              ///< s
  virtual double maxFrequencyHz() const = 0;        ///< highest frequency it contains
  virtual std::string describe() const = 0;
};

/// x = A e(t) sin(2 pi f t), e = 1, or with a ramp-in of `ramp` s a raised cosine
/// 1/2 (1 - cos(pi t / ramp)) until then: the motion starts from rest, without the
/// velocity jump that rings a structure's high modes.
std::unique_ptr<TableProgram> sineDwell(double amplitude, double frequency_hz, double duration, double ramp = 0);
/// x = A sin(phi(t)) with the instantaneous frequency phi'/(2 pi) going from f0 to f1
/// over T, linearly or exponentially (log sweep); before 0 and after T it dwells at f0
/// and f1 (the phase continuous), as a sine dwell runs on past its duration.
std::unique_ptr<TableProgram> sineSweep(double amplitude, double f0_hz, double f1_hz, double duration, bool logarithmic);
/// Band-limited random: n_lines sinusoids of equal amplitude, evenly spaced between
/// f_lo and f_hi, with phases drawn from a seeded generator; RMS displacement `rms`.
std::unique_ptr<TableProgram> bandLimitedRandom(double rms, double f_lo_hz, double f_hi_hz, double duration,
                                                std::uint64_t seed, int n_lines = 200);
/// A deterministic profile read from CSV text with a header `time_s,x_m` (or
/// `time_s,torque_n_m`, `time_s,angle_deg`, `time_s,force_n`: the values as read): piecewise
/// cubic Hermite through the samples (Catmull-Rom slopes), at rest before and after.
/// Throws std::invalid_argument "source:line: what is wrong".
std::unique_ptr<TableProgram> csvProfile(const std::string& csv_text, const std::string& source);

struct ProgramCheck {
  bool within_stroke = true;
  double peak_displacement = 0;  ///< m
  double peak_acceleration = 0;  ///< m/s^2
  bool above_bandwidth = false;  ///< content above the servo bandwidth (it will be attenuated)
  std::vector<std::string> messages;  ///< one per problem, for the user
};

/// Samples the program over [0, min(horizon, duration)] (20 points per period of its
/// highest frequency) and checks it against the table. Exceeding the stroke is an
/// error (within_stroke = false). horizon <= 0: the program's whole duration.
ProgramCheck checkProgram(const TableProgram& p, const TableSpec& table = {}, double horizon = 0);

}  // namespace mmv::facility

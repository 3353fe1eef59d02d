#pragma once
/// The extra shaker of the Ground Test Facility (report, "Test Facility": "a 30 lb
/// long-stroke shaker for excitation away from the base"; docs/sources.md section 2):
/// an electrodynamic exciter on a stand, driving the article through a stinger at one
/// point along one direction.
///
/// The report gives its force only. Its stroke and moving (armature) mass are chosen
/// here (`assumed` below, typical of a 30 lbf long-stroke modal shaker) and every one can
/// be set in the scene (`shaker:`), as the lab's own shaker's data sheet states them. The
/// stinger is taken as rigid along its axis and free across it: the article feels the
/// force along the direction and the armature's mass, nothing else.

namespace mmv::facility {

constexpr double kPoundForce = 4.4482216152605;  ///< N.

struct ShakerSpec {
  double force_limit = 30 * kPoundForce;  ///< N, peak sine force (report: 30 lb).
  // Assumed (not in the report):
  double stroke = 0.075;         ///< m, +- about the centre (assumed: a 150 mm peak-to-peak long stroke).
  double armature_mass = 0.5;    ///< kg moving with the article at the attachment (assumed: armature, stinger, force gauge).
  /// The crest factor of a random program: its peak force over its RMS. A random run's
  /// RMS force is force_limit / crest_factor (assumed: 3, a Gaussian signal clipped at 3 sigma).
  double crest_factor = 3;
};

}  // namespace mmv::facility

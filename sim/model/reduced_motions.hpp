#pragma once
/// Acceleration-level Motions for time runs in reduced coordinates (links carried by
/// their modes, sim/time/modal_links.hpp). Every mobilizer that no other Motion drives
/// gets one, disabled by default, so statics, modes and linearization never see it; a
/// reduced run enables them in its own State and sets the accelerations they prescribe.
/// Realized to Acceleration, such a State is then wholly prescribed: Simbody computes
/// the motion forces each mobility needs (inverse dynamics), and every output of the
/// run (point accelerations, joint torques, the energy books) comes out of the reduced
/// model's motion.

#include <Simbody.h>

#include <vector>

namespace mmv {

class ReducedMotions {
 public:
  /// Adds a Motion to each of `mobods` (call before the system's topology is realized);
  /// `nu` is the system's number of mobilities.
  void addTo(SimTK::SimbodyMatterSubsystem& matter, const std::vector<SimTK::MobilizedBodyIndex>& mobods, int nu);
  bool empty() const { return mobods_.empty(); }
  /// The mobilizers that carry one.
  const std::vector<SimTK::MobilizedBodyIndex>& mobilizers() const { return mobods_; }
  /// Enables them in `s` (Instance stage).
  void enable(const SimTK::SimbodyMatterSubsystem& matter, SimTK::State& s) const;
  /// The accelerations they prescribe, in u order (entries of other mobilities unused).
  void setAccelerations(SimTK::State& s, const SimTK::Vector& udot) const;

 private:
  std::vector<SimTK::MobilizedBodyIndex> mobods_;
  SimTK::Measure_<SimTK::Vector>::Variable udot_;
};

}  // namespace mmv

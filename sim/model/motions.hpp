#pragma once
/// Prescribed motions in time runs: a locked joint following a torquer slew
/// (facility/slews.hpp) and a mobilizer following a table or ground motion program
/// (facility/table_programs.hpp), as Simbody custom Motions with the position, its
/// rate and its acceleration given analytically. Statics and modes do not see them.

#include <Simbody.h>

#include <functional>
#include <memory>

#include "facility/slews.hpp"
#include "facility/table_programs.hpp"
#include "sim/scene/programs.hpp"

namespace mmv {

/// A prescribed coordinate over time: what a run in reduced coordinates
/// (sim/time/modal_links.hpp) needs without realizing Simbody's stages.
struct PrescribedMotion {
  /// Position (rad or m) and rate; empty for a coordinate held where the state has it,
  /// at rest (a locked joint).
  std::function<double(double t)> q, u;
  std::function<double(double t)> udot;  ///< rad/s^2 or m/s^2
};

/// Prescribes a one-coordinate mobilizer's position by a program; returns the motion.
PrescribedMotion prescribeTableProgram(SimTK::MobilizedBody& mobod, std::shared_ptr<const facility::TableProgram> program);

/// Prescribes a one-coordinate mobilizer's angle by a slew that starts at `start_s` (s);
/// returns the motion.
PrescribedMotion prescribeSlew(SimTK::MobilizedBody& mobod, const facility::Slew& slew, double start_s);

/// Holds a one-coordinate mobilizer at rest where the state has it (Simbody's Steady
/// Motion at 0); returns the motion.
PrescribedMotion prescribeRest(SimTK::MobilizedBody& mobod);

}  // namespace mmv

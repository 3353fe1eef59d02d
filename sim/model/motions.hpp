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

/// A prescribed coordinate's acceleration over time (rad/s^2 or m/s^2): what a run in
/// reduced coordinates (sim/time/modal_links.hpp) needs without realizing Acceleration.
using PrescribedAcceleration = std::function<double(double t)>;

/// Prescribes a one-coordinate mobilizer's position by a program; returns its acceleration.
PrescribedAcceleration prescribeTableProgram(SimTK::MobilizedBody& mobod, std::shared_ptr<const facility::TableProgram> program);

/// Prescribes a one-coordinate mobilizer's angle by a slew that starts at `start_s` (s);
/// returns its acceleration.
PrescribedAcceleration prescribeSlew(SimTK::MobilizedBody& mobod, const facility::Slew& slew, double start_s);

}  // namespace mmv

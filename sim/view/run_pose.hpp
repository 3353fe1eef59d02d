#pragma once
/// A recorded run's pose, for drawing it (sim/io/run_dir.hpp reads the run; the command
/// picks the row).

#include <vector>

#include "sim/model/model.hpp"

namespace mmv {

/// `row` (a states.csv row: time_s, then the model's coordinates in order) into `s` at
/// time t, realized to Position.
void setRunPose(const std::vector<double>& row, double t, const Model& model, SimTK::State& s);

}  // namespace mmv

#include "sim/view/run_pose.hpp"

#include "sim/core/errors.hpp"

namespace mmv {

void setRunPose(const std::vector<double>& row, double t, const Model& model, SimTK::State& s) {
  MMV_DEMAND(row.size() == static_cast<std::size_t>(model.getNumCoordinates()) + 1);  // checkRunModel held the columns
  for (int i = 0; i < model.getNumCoordinates(); ++i) s.updQ()[model.getQIndex(i)] = row[static_cast<std::size_t>(i) + 1];
  s.setTime(t);
  model.getSystem().realize(s, SimTK::Stage::Position);
}

}  // namespace mmv

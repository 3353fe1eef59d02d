#pragma once
/// Mode tracking across a parameter change: modes keep their identity by shape, not
/// by their rank in frequency, so crossing and veering modes are followed.

#include <Eigen/Dense>
#include <vector>

namespace mmv {

struct ModeMatch {
  std::vector<int> index;   ///< for each previous shape, the column of `current` it became.
  std::vector<double> mac;  ///< and the MAC of that pair.
};

/// Pairs each column of `previous` with a distinct column of `current` (both as
/// shapes at the same points), greedily by descending MAC: the most alike pair
/// first. `current` must have at least as many columns as `previous`.
ModeMatch matchModes(const Eigen::MatrixXd& previous, const Eigen::MatrixXd& current);

}  // namespace mmv

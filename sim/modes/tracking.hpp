#pragma once
/// Mode tracking across a parameter change: modes keep their identity by shape, not
/// by their rank in frequency, so crossing and veering modes are followed.

#include <Eigen/Dense>
#include <vector>

namespace mmv {

/// The assignment of each row of `cost` (n x m, n <= m) to a distinct column with the
/// least total cost: the Hungarian method, O(n^2 m). Entry i is row i's column.
std::vector<int> optimalAssignment(const Eigen::MatrixXd& cost);

struct ModeMatch {
  std::vector<int> index;   ///< for each previous shape, the column of `current` it became.
  std::vector<double> mac;  ///< and the MAC of that pair.
};

/// Pairs each column of `previous` with a distinct column of `current` (both as
/// shapes at the same points) so that the sum of the pairs' MAC is largest (an optimal
/// assignment: a greedy "most alike pair first" can take the one shape two modes
/// both resemble and leave the second with a poor partner). `current` must have at
/// least as many columns as `previous`.
ModeMatch matchModes(const Eigen::MatrixXd& previous, const Eigen::MatrixXd& current);

}  // namespace mmv

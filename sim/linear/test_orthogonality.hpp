#pragma once
/// Test orthogonality: the measured modes at a TAM's channels, orthogonal under the TAM
/// mass (`correlate --tam`; the TAM from `place-sensors --tam --out`, tam.mat). With the
/// measured shapes at the channels V (a x t, each real: a complex shape turned to the
/// phase that makes it most nearly real, then its real part), O = V^T M_tam V,
/// normalised O_ij / sqrt(O_ii O_jj); a mode passes when its largest off-diagonal is at
/// most kTamOffDiagonalMax (0.1, NASA-STD-5002). A measured mode that lacks a channel's
/// node is left out and named.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "sim/linear/correlation.hpp"

namespace mmv {

struct TamChannels {
  std::string source, method;     ///< the file and the reduction (guyan, irs, serep)
  Eigen::MatrixXd M;              ///< a x a
  std::vector<int> nodes;         ///< per channel, its test-geometry node
  std::vector<std::array<double, 3>> directions;  ///< per channel, its world unit vector
  std::vector<std::string> names; ///< per channel, "station axis"
};

struct TestOrthogonality {
  std::string source, method;
  int channels = 0;
  std::vector<int> modes;              ///< the measured modes' numbers, in the matrix's order
  std::vector<double> frequencies_hz;
  Eigen::MatrixXd matrix;              ///< normalised, modes x modes
  std::vector<double> max_off_diagonal;  ///< per mode
  std::vector<char> pass;              ///< per mode
  std::vector<std::string> left_out;   ///< measured modes left out, with the reason
  bool all_pass = false;
};

/// Throws SceneError when no measured mode has every channel's node.
TestOrthogonality testOrthogonality(const MeasuredSet& test, const TamChannels& tam);

}  // namespace mmv

#pragma once
/// MATLAB/Octave .mat (version 5) export of a state-space model through matio:
/// double matrices A, B, C, D, E (E = I: A and B are in standard form, so
/// `sys = ss(A, B, C, D)` works directly), the descriptor form as Ed, Ad, Bd, and cell
/// arrays InputName, OutputName, StateName, InputUnit, OutputUnit.

#include <string>
#include <utility>
#include <vector>

#include "sim/linear/state_space.hpp"

namespace mmv {

/// What a .mat file holds: named double matrices and named cell arrays of strings.
struct MatContents {
  std::vector<std::pair<std::string, Eigen::MatrixXd>> matrices;
  std::vector<std::pair<std::string, std::vector<std::string>>> strings;
};

/// Writes `path` (MAT 5) and reads every variable back (matio buffers its writes: a full
/// disk surfaces there); throws OutputError.
void writeMat(const std::string& path, const MatContents& contents);

/// Reads `path`: every double matrix and every cell array of strings in it. Throws
/// SceneFileError when it does not open or is larger than `max_bytes`, SceneError when a
/// variable is neither.
MatContents readMat(const std::string& path, long max_bytes);

/// Writes `path`; throws std::runtime_error if matio cannot create or write it.
void writeStateSpaceMat(const std::string& path, const StateSpace& descriptor);

}  // namespace mmv

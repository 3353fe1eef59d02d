#pragma once
/// MATLAB/Octave .mat (version 5) export of a state-space model through matio:
/// double matrices A, B, C, D, E (E = I: A and B are in standard form, so
/// `sys = ss(A, B, C, D)` works directly), the descriptor form as Ed, Ad, Bd, and cell
/// arrays InputName, OutputName, StateName, InputUnit, OutputUnit.

#include <string>

#include "sim/linear/state_space.hpp"

namespace mmv {

/// Writes `path`; throws std::runtime_error if matio cannot create or write it.
void writeStateSpaceMat(const std::string& path, const StateSpace& descriptor);

}  // namespace mmv

#pragma once
/// A linear model's response in time, for what a run of the full model would record
/// (`check`'s sensor peaks under the table's program).
#include <functional>

#include <Eigen/Dense>

#include "sim/linear/state_space.hpp"

namespace mmv {

/// The outputs y(t_k), t_k = k dt for k = 0..steps (rows), of E x' = A x + B u,
/// y = C x + D u from rest (x(0) = 0), for inputs `u(t)` taken linear between the
/// samples: exact for such inputs (the matrix exponential of the system augmented with
/// the input and its slope: a first-order hold), at any dt, stiff modes included.
/// O(steps N^2) after one exponential of size N + 2 inputs.
Eigen::MatrixXd timeResponse(const StateSpace& s, const std::function<Eigen::VectorXd(double)>& u, double dt, int steps);

}  // namespace mmv

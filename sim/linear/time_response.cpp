#include "sim/linear/time_response.hpp"

#include <unsupported/Eigen/MatrixFunctions>

#include "sim/core/errors.hpp"

namespace mmv {

Eigen::MatrixXd timeResponse(const StateSpace& s, const std::function<Eigen::VectorXd(double)>& u, double dt, int steps) {
  MMV_DEMAND(dt > 0 && steps >= 0);
  const StateSpace f = s.standardForm();
  const Eigen::Index n = f.A.rows(), m = f.B.cols();
  // exp(dt [A B 0; 0 0 I; 0 0 0]) = [Phi G1 G2; ...]: x_{k+1} = Phi x_k + G1 u_k + G2 (u_{k+1} - u_k) / dt.
  Eigen::MatrixXd aug = Eigen::MatrixXd::Zero(n + 2 * m, n + 2 * m);
  aug.topLeftCorner(n, n) = f.A * dt;
  aug.block(0, n, n, m) = f.B * dt;
  aug.block(n, n + m, m, m) = Eigen::MatrixXd::Identity(m, m) * dt;
  const Eigen::MatrixXd e = aug.exp();
  if (!e.allFinite()) throw NumericalError("time response: the matrix exponential of the linear model is not finite");
  const Eigen::MatrixXd Phi = e.topLeftCorner(n, n), G1 = e.block(0, n, n, m), G2 = e.block(0, n + m, n, m);
  Eigen::MatrixXd y(steps + 1, f.C.rows());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), u0 = u(0.0);
  MMV_DEMAND(u0.size() == m);
  y.row(0) = (f.C * x + f.D * u0).transpose();
  for (int k = 1; k <= steps; ++k) {
    const Eigen::VectorXd u1 = u(k * dt);
    x = Phi * x + G1 * u0 + G2 * ((u1 - u0) / dt);
    y.row(k) = (f.C * x + f.D * u1).transpose();
    u0 = u1;
  }
  return y;
}

}  // namespace mmv

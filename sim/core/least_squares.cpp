#include "sim/core/least_squares.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The problem in scaled variables u = p / scale, with the regularization's rows.
struct Scaled {
  const LeastSquaresProblem& problem;
  Eigen::VectorXd lo, hi, u0;
  int evaluations = 0;

  explicit Scaled(const LeastSquaresProblem& p)
      : problem(p), lo(p.lower.cwiseQuotient(p.scale)), hi(p.upper.cwiseQuotient(p.scale)), u0(p.start.cwiseQuotient(p.scale)) {}

  Eigen::VectorXd clamp(const Eigen::VectorXd& u) const { return u.cwiseMax(lo).cwiseMin(hi); }

  /// The data's residuals at u (nullopt: refused); a non-finite one is an error.
  std::optional<Eigen::VectorXd> data(const Eigen::VectorXd& u) {
    ++evaluations;
    std::optional<Eigen::VectorXd> r = problem.residuals(u.cwiseProduct(problem.scale));
    if (r && !r->allFinite()) throw NumericalError("model updating: a residual is not finite at a trial point");
    return r;
  }
  Eigen::VectorXd augmented(const Eigen::VectorXd& r, const Eigen::VectorXd& u) const {
    if (problem.regularization <= 0) return r;
    Eigen::VectorXd a(r.size() + u.size());
    a << r, problem.regularization * (u - u0);
    return a;
  }

  /// d r / d u by central differences (one-sided at a bound or where a side is refused).
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& u, const Eigen::VectorXd& r, double h) {
    Eigen::MatrixXd J(r.size(), u.size());
    for (Eigen::Index k = 0; k < u.size(); ++k) {
      Eigen::VectorXd up = u, down = u;
      up(k) += h, down(k) -= h;
      const bool can_up = up(k) <= hi(k), can_down = down(k) >= lo(k);
      std::optional<Eigen::VectorXd> rp = can_up ? data(up) : std::nullopt;
      std::optional<Eigen::VectorXd> rm = can_down ? data(down) : std::nullopt;
      if (rp && rm) J.col(k) = (*rp - *rm) / (2 * h);
      else if (rp) J.col(k) = (*rp - r) / h;
      else if (rm) J.col(k) = (r - *rm) / h;
      else throw NumericalError("model updating: the residuals cannot be evaluated on either side of a parameter's value");
    }
    if (problem.regularization <= 0) return J;
    Eigen::MatrixXd A(J.rows() + u.size(), u.size());
    A << J, problem.regularization * Eigen::MatrixXd::Identity(u.size(), u.size());
    return A;
  }
};

/// Per parameter: free, or held on a bound that descent (-g) would leave the box through.
std::vector<bool> freeParameters(const Eigen::VectorXd& g, const Eigen::VectorXd& u, const Eigen::VectorXd& lo,
                                 const Eigen::VectorXd& hi) {
  std::vector<bool> free(static_cast<std::size_t>(g.size()));
  for (Eigen::Index k = 0; k < g.size(); ++k)
    free[static_cast<std::size_t>(k)] = !((u(k) <= lo(k) && g(k) > 0) || (u(k) >= hi(k) && g(k) < 0));
  return free;
}

/// The damped Gauss-Newton step over the free parameters (the held ones do not move).
Eigen::VectorXd dampedStep(const Eigen::MatrixXd& A, const Eigen::VectorXd& g, const Eigen::VectorXd& D, double lambda,
                           const std::vector<bool>& free) {
  std::vector<Eigen::Index> f;
  for (Eigen::Index k = 0; k < g.size(); ++k)
    if (free[static_cast<std::size_t>(k)]) f.push_back(k);
  const Eigen::Index m = static_cast<Eigen::Index>(f.size());
  Eigen::MatrixXd Af(m, m);
  Eigen::VectorXd gf(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    gf(i) = g(f[static_cast<std::size_t>(i)]);
    for (Eigen::Index j = 0; j < m; ++j) Af(i, j) = A(f[static_cast<std::size_t>(i)], f[static_cast<std::size_t>(j)]);
    Af(i, i) += lambda * D(f[static_cast<std::size_t>(i)]);
  }
  const Eigen::VectorXd sf = Af.ldlt().solve(-gf);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(g.size());
  for (Eigen::Index i = 0; i < m; ++i) step(f[static_cast<std::size_t>(i)]) = sf(i);
  return step;
}

}  // namespace

double studentT975(int dof) {
  static constexpr double kTable[30] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                        2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                        2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  MMV_DEMAND(dof >= 1);
  if (dof <= 30) return kTable[dof - 1];
  const double z = 1.959963984540054, v = dof;  // Cornish-Fisher expansion about the normal quantile
  return z + (z * z * z + z) / (4 * v) + (5 * std::pow(z, 5) + 16 * z * z * z + 3 * z) / (96 * v * v);
}

Identifiability identifiability(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const Eigen::VectorXd& scale,
                                double undetermined_below, double collinearity_above) {
  const Eigen::Index m = J.rows(), n = J.cols();
  Identifiability id;
  id.undetermined_below = undetermined_below, id.collinearity_above = collinearity_above;
  const Eigen::MatrixXd Ju = J * scale.asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ju, Eigen::ComputeFullV);
  id.singular_values = Eigen::VectorXd::Zero(n);
  id.singular_values.head(svd.singularValues().size()) = svd.singularValues();
  id.directions = svd.matrixV();
  for (Eigen::Index i = 0; i < n; ++i)
    if (id.singular_values(i) < undetermined_below) id.undetermined.push_back(static_cast<int>(i));
  id.degrees_of_freedom = static_cast<int>(m - n);
  if (m > n) id.residual_variance = r.squaredNorm() / static_cast<double>(m - n);
  id.determined.assign(static_cast<std::size_t>(n), true);
  const auto undetermine = [&id](const Eigen::VectorXd& v) {
    for (Eigen::Index k = 0; k < v.size(); ++k)
      if (std::abs(v(k)) >= 0.1) id.determined[static_cast<std::size_t>(k)] = false;
  };
  for (const int i : id.undetermined) undetermine(id.directions.col(i));
  // Collinearity over the column-normalised sensitivities (a zero column is undetermined above).
  Eigen::MatrixXd Jn = Ju;
  for (Eigen::Index k = 0; k < n; ++k)
    if (const double c = Jn.col(k).norm(); c > 0) Jn.col(k) /= c;
  Eigen::JacobiSVD<Eigen::MatrixXd> nsvd(Jn, Eigen::ComputeFullV);
  Eigen::VectorXd sn = Eigen::VectorXd::Zero(n);
  sn.head(nsvd.singularValues().size()) = nsvd.singularValues();
  for (Eigen::Index i = 0; i < n; ++i)
    if (sn(i) * collinearity_above < 1) {
      const double index = sn(i) > 0 ? 1 / sn(i) : std::numeric_limits<double>::infinity();
      id.collinear.push_back({index, nsvd.matrixV().col(i)});
      undetermine(nsvd.matrixV().col(i));
    }
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);  // scaled, over the determined directions
  for (Eigen::Index i = 0; i < n; ++i)
    if (std::find(id.undetermined.begin(), id.undetermined.end(), i) == id.undetermined.end())
      C += id.directions.col(i) * id.directions.col(i).transpose() / (id.singular_values(i) * id.singular_values(i));
  id.standard_error = Eigen::VectorXd::Constant(n, kNaN);
  id.interval_half_width = Eigen::VectorXd::Constant(n, kNaN);
  id.correlation = Eigen::MatrixXd::Constant(n, n, kNaN);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!id.determined[static_cast<std::size_t>(k)]) continue;
    for (Eigen::Index j = 0; j < n; ++j)
      if (id.determined[static_cast<std::size_t>(j)] && C(k, k) > 0 && C(j, j) > 0)
        id.correlation(k, j) = C(k, j) / std::sqrt(C(k, k) * C(j, j));
    if (!id.residual_variance) continue;
    id.standard_error(k) = scale(k) * std::sqrt(*id.residual_variance * C(k, k));
    id.interval_half_width(k) = studentT975(id.degrees_of_freedom) * id.standard_error(k);
  }
  return id;
}

LeastSquaresResult solveBoundedLeastSquares(const LeastSquaresProblem& problem, const LeastSquaresOptions& o) {
  const Eigen::Index n = problem.start.size();
  MMV_DEMAND(n > 0 && problem.lower.size() == n && problem.upper.size() == n && problem.scale.size() == n);
  MMV_DEMAND((problem.scale.array() > 0).all() && (problem.lower.array() <= problem.upper.array()).all());
  Scaled s(problem);
  Eigen::VectorXd u = s.clamp(s.u0);
  std::optional<Eigen::VectorXd> r0 = s.data(u);
  if (!r0) throw NumericalError("model updating: the model cannot be evaluated at the start");
  Eigen::VectorXd r = *r0, a = s.augmented(r, u);
  double cost = 0.5 * a.squaredNorm(), lambda = -1, nu = 2;
  LeastSquaresResult out;
  out.iterations.push_back({0, u.cwiseProduct(problem.scale), cost, 0, s.evaluations});
  out.stop = "the iteration limit";
  Eigen::MatrixXd J;  // the Jacobian at u_J (reused at the end when no step moved u since)
  Eigen::VectorXd u_J;
  for (int it = 1; it <= o.max_iterations; ++it) {
    J = s.jacobian(u, r, o.difference_step), u_J = u;
    const Eigen::MatrixXd A = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * a;
    const std::vector<bool> free = freeParameters(g, u, s.lo, s.hi);
    double projected = 0;  // the gradient's largest component along which descent stays in the box
    for (Eigen::Index k = 0; k < g.size(); ++k)
      if (free[static_cast<std::size_t>(k)]) projected = std::max(projected, std::abs(g(k)));
    if (projected <= o.gradient_tolerance * std::max(1.0, cost)) {
      out.converged = true, out.stop = "the gradient vanished";
      break;
    }
    const Eigen::VectorXd D = A.diagonal().cwiseMax(1e-12 * std::max(A.diagonal().maxCoeff(), 1e-300));
    if (lambda < 0) lambda = 1e-3;
    bool accepted = false, done = false;
    for (int tries = 0; tries < 40 && !accepted; ++tries) {
      const Eigen::VectorXd step = dampedStep(A, g, D, lambda, free);
      const Eigen::VectorXd u_new = s.clamp(u + step), taken = u_new - u;
      if (taken.cwiseAbs().maxCoeff() <= o.step_tolerance * (1 + u.cwiseAbs().maxCoeff())) {
        done = true, out.converged = true, out.stop = "the step fell below its tolerance";
        break;
      }
      const std::optional<Eigen::VectorXd> r_new = s.data(u_new);
      const double cost_new = r_new ? 0.5 * s.augmented(*r_new, u_new).squaredNorm() : 0;
      if (!r_new || cost_new >= cost) {
        lambda *= nu, nu *= 2;
        continue;
      }
      const double predicted = -(taken.dot(g) + 0.5 * taken.dot(A * taken));
      const double rho = predicted > 0 ? (cost - cost_new) / predicted : 0;
      lambda *= std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3)), nu = 2;
      const double decrease = cost - cost_new;
      u = u_new, r = *r_new, a = s.augmented(r, u);
      cost = cost_new, accepted = true;
      out.iterations.push_back({it, u.cwiseProduct(problem.scale), cost, lambda, s.evaluations});
      if (decrease <= o.cost_tolerance * cost_new || cost_new == 0)
        done = true, out.converged = true, out.stop = "the cost stopped decreasing";
      else if (taken.cwiseAbs().maxCoeff() <= o.step_tolerance * (1 + u.cwiseAbs().maxCoeff()))
        done = true, out.converged = true, out.stop = "the step fell below its tolerance";
    }
    if (!accepted && !done) {  // lambda grew 2^40-fold: the gradient is at round-off
      out.converged = true, out.stop = "no step lowers the cost (its round-off floor)";
      break;
    }
    if (done) break;
  }
  out.p = u.cwiseProduct(problem.scale);
  out.residuals = r;
  out.cost = cost;
  if (u_J.size() != u.size() || u_J != u) J = s.jacobian(u, r, o.difference_step);
  out.jacobian = J.topRows(r.size()) * problem.scale.cwiseInverse().asDiagonal();
  out.evaluations = s.evaluations;
  for (Eigen::Index k = 0; k < n; ++k)
    out.at_bound.push_back(u(k) <= s.lo(k) + 1e-12 * std::abs(s.lo(k)) || u(k) >= s.hi(k) - 1e-12 * std::abs(s.hi(k)));
  out.identifiability = identifiability(out.jacobian, r, problem.scale, o.undetermined_below, o.collinearity_above);
  return out;
}

}  // namespace mmv

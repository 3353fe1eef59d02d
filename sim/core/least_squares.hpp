#pragma once
/// Bounded nonlinear least squares (Levenberg-Marquardt) and what the fit can say about
/// its parameters: the numerical core of `mmvlab update` (sim/app/update_study.hpp),
/// free of scenes so that it is tested on problems with known answers.
///
///  - Variables are the parameters divided by their scales (a relative change of 1 is a
///    change of one scale), so moduli in Pa and masses in kg are steps of one size.
///  - The Jacobian is taken by central differences of the residuals, one-sided at a
///    bound (the residual function may refuse a point: a trial step there is shrunk).
///  - A step is projected onto the bounds; the damping follows Marquardt (the diagonal
///    of J^T J, floored) and Nielsen's update; the iteration stops when the step, the
///    cost's relative decrease or the projected gradient falls below its tolerance.
///  - Identifiability at the solution, from the scaled Jacobian J (residuals per change of
///    one scale):
///     - a combination (a right singular vector of J) is not determined when a change of
///       one scale along it moves the weighted residuals by less than
///       `undetermined_below` (with weights 1 / sigma: less than the data's stated
///       uncertainty);
///     - parameters are collinear when their sensitivities nearly repeat one another:
///       with J's columns normalised to length 1, a singular value s_n below
///       1 / `collinearity_above` makes its combination's parameters not determined,
///       only the combination's orthogonal complement is (Brun, Reichert and Kuensch's
///       collinearity index 1 / s_n; they call 10-15 critical; two parameters at index
///       20 correlate at 0.9975). Sensitivities of very different sizes (a parameter
///       that moves the residuals 100x more than another) are not collinear.
///    A parameter with a component of 0.1 or more in such a combination is "not
///    determined": its standard error and interval are NaN.
///    Covariance s^2 (J^T J)^-1 over the determined directions, s^2 the residual
///    variance r^T r / (m - n) (none when m <= n), 95 % intervals with Student's t.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace mmv {

struct LeastSquaresProblem {
  /// Weighted residuals at parameters p (physical units); nullopt: p cannot be evaluated
  /// (the step is shrunk, never taken).
  std::function<std::optional<Eigen::VectorXd>(const Eigen::VectorXd& p)> residuals;
  Eigen::VectorXd start, lower, upper, scale;  ///< scale > 0 per parameter.
  /// Weight of the pull toward `start`, in residuals per unit scaled change (0: none).
  double regularization = 0;
};

struct LeastSquaresOptions {
  int max_iterations = 50;
  double step_tolerance = 1e-9;       ///< on the scaled step's largest component (relative to 1 + |u|).
  double cost_tolerance = 1e-12;      ///< on the cost's relative decrease.
  double gradient_tolerance = 1e-12;  ///< on the projected scaled gradient's largest component.
  /// Scaled central-difference step: a model solved to ~1e-12 (equilibrium, eigenvalues)
  /// differenced over 1e-4 keeps the round-off near 1e-8, and the truncation as small.
  double difference_step = 1e-4;
  double undetermined_below = 1.0;    ///< see above.
  double collinearity_above = 20;     ///< see above.
};

struct LeastSquaresIteration {
  int iteration = 0;
  Eigen::VectorXd p;
  double cost = 0;     ///< 0.5 |r|^2 (with the regularization's rows).
  double damping = 0;  ///< Marquardt's lambda for the step that reached p.
  int evaluations = 0; ///< residual evaluations so far.
};

struct Identifiability {
  Eigen::VectorXd singular_values;  ///< of the scaled Jacobian, largest first.
  Eigen::MatrixXd directions;       ///< columns: the scaled parameter combinations, in order.
  std::vector<int> undetermined;    ///< indices of directions the data do not determine.
  /// Collinear combinations: the collinearity index and the combination (over the
  /// column-normalised sensitivities), one per index above the criterion.
  std::vector<std::pair<double, Eigen::VectorXd>> collinear;
  double undetermined_below = 1, collinearity_above = 20;  ///< the criteria used.
  std::optional<double> residual_variance;  ///< r^T r / (m - n); none when m <= n.
  int degrees_of_freedom = 0;       ///< m - n
  Eigen::VectorXd standard_error;   ///< physical units; NaN for a parameter in an undetermined combination.
  Eigen::VectorXd interval_half_width;  ///< 95 %, physical units; NaN as above or without a variance.
  Eigen::MatrixXd correlation;      ///< NaN where undefined.
  std::vector<bool> determined;     ///< per parameter: not part of an undetermined combination.
};

struct LeastSquaresResult {
  Eigen::VectorXd p, residuals;  ///< at the solution (residuals without the regularization's rows).
  Eigen::MatrixXd jacobian;      ///< d residuals / d p (physical units), at p.
  double cost = 0;
  bool converged = false;
  std::string stop;  ///< why it stopped, in words.
  std::vector<LeastSquaresIteration> iterations;  ///< [0] the start.
  std::vector<bool> at_bound;  ///< per parameter: on its lower or upper bound at the end.
  Identifiability identifiability;
  int evaluations = 0;
};

/// Solves the problem (see above). Throws NumericalError when the start cannot be
/// evaluated or a residual is not finite.
LeastSquaresResult solveBoundedLeastSquares(const LeastSquaresProblem& problem, const LeastSquaresOptions& options = {});

/// Identifiability of parameters with Jacobian `jacobian` (physical units), residuals `r`
/// and scales `scale` (see above).
Identifiability identifiability(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& r, const Eigen::VectorXd& scale,
                                double undetermined_below = 1.0, double collinearity_above = 20);

/// Student's t quantile for probability 0.975 with `dof` >= 1 degrees of freedom.
double studentT975(int dof);

}  // namespace mmv

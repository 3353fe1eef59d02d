#pragma once
// A square solve that is judged on the problem, not on raw pivots: the matrix is
// equilibrated first (rows, then columns, scaled to unit largest entry), so a model
// whose stiffnesses span many decades (a link of E = 1e20 Pa beside a slender rod:
// 4e13 and 2.6 N*m/rad in one chain) is not declared singular by a pivot threshold
// relative to its largest entry. A matrix with an all-zero row or column is singular.
#include <Eigen/Dense>

namespace mmv {

/// A := (A + A^T) / 2 exactly (each pair averaged once). Written out because
/// `A = 0.5 * (A + A.transpose())` aliases in Eigen: entries are overwritten before
/// their mirror is read, and the result is not symmetric.
void symmetrize(Eigen::MatrixXd& A);

class EquilibratedLu {
 public:
  explicit EquilibratedLu(const Eigen::MatrixXd& A);
  /// Whether A is invertible to working precision once equilibrated.
  bool isInvertible() const { return ok_; }
  /// A^-1 B (call only when isInvertible()).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

 private:
  Eigen::VectorXd r_, c_;
  Eigen::FullPivLU<Eigen::MatrixXd> lu_;
  bool ok_ = false;
};

}  // namespace mmv

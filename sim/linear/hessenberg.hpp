// Shared by the linear models' frequency responses (sim/linear/second_order.cpp, the full
// model's Hessenberg path; sim/linear/state_space.cpp, a state-space model's responses):
// balancing and the elimination of i w I - H for an upper Hessenberg H.
#pragma once

#include <Eigen/Dense>
#include <complex>
#include <vector>

namespace mmv::detail {

using RowMajorXcd = Eigen::Matrix<std::complex<double>, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMajorXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Parlett-Reinsch balancing (as LAPACK's dgebal, without permutations): A := D^-1 A D
/// with D a diagonal of powers of two (exact), each row and column brought to a similar
/// norm; returns D's diagonal.
Eigen::VectorXd balance(Eigen::MatrixXd& A);

/// i w I - H (H upper Hessenberg) eliminated to upper triangular U by adjacent-row
/// partial pivoting: step k swaps rows k, k+1 if swap[k], then row k+1 -= l[k] row k.
/// U's rows are packed (row k holds columns k..N-1) with real and imaginary parts apart
/// (real vector arithmetic, twice as wide as complex), in buffers each thread keeps, so
/// a frequency neither copies H nor touches fresh pages: one alive per thread at a time.
/// H has at least one row.
class HessenbergLu {
 public:
  HessenbergLu(const RowMajorXd& H, double w);

  /// Solves in place (rows of X over the N states).
  void solve(RowMajorXcd& X) const;

 private:
  Eigen::Index offset(Eigen::Index k) const { return k * N_ - k * (k - 1) / 2; }
  Eigen::Index N_;
  std::vector<char> swap_;
  std::vector<std::complex<double>> l_;
  double *re_, *im_;
};

}  // namespace mmv::detail

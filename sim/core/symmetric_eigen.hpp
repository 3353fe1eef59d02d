#pragma once
// Every eigenpair of a dense symmetric matrix, by Householder tridiagonalization (Eigen),
// LAPACK's MRRR on the tridiagonal (dstemr: O(n^2) for all eigenvectors, where the
// implicit QR Eigen uses accumulates O(n^3) rotations) and the reflectors applied back
// in blocks: on the default article's 256 DOF (64 segments a link) 9.3 ms against 12.5
// for Eigen's SelfAdjointEigenSolver, 52 against 101 ms at 512 DOF; below about 150 DOF
// Eigen's is as fast or faster and is used (bench/modes_bench.cpp, BM_SymmetricEigen*;
// docs/benchmarks.md). Where dstemr reports a failure or returns anything non-finite,
// Eigen's solver is used instead.
#include <Eigen/Dense>

namespace mmv {

struct SymmetricEigen {
  Eigen::VectorXd values;   ///< ascending
  Eigen::MatrixXd vectors;  ///< orthonormal columns, values' order
  bool by_mrrr = false;     ///< false: Eigen's implicit QR (n < kMrrrMinSize, or dstemr failed)
};

/// From this size on, MRRR; below it, Eigen's implicit QR.
inline constexpr long kMrrrMinSize = 192;

/// Every eigenpair of the symmetric tridiagonal matrix (diagonal d, sub-diagonal e with a
/// trailing slot; both overwritten) into `values` (ascending) and the columns of `Z`
/// (n x n, allocated by the caller). Returns LAPACK's info: 0 on success. `m` is the
/// number of eigenpairs found.
using TridiagonalEigenSolver = int (*)(Eigen::VectorXd& d, Eigen::VectorXd& e, Eigen::VectorXd& values,
                                       Eigen::MatrixXd& Z, int& m);

/// LAPACK's dstemr (MRRR), the production tridiagonal solver.
int mrrrTridiagonal(Eigen::VectorXd& d, Eigen::VectorXd& e, Eigen::VectorXd& values, Eigen::MatrixXd& Z, int& m);

/// All eigenpairs of the symmetric S (its lower triangle is read). Throws NumericalError
/// if neither method converges or S has non-finite entries. `tridiagonal` is the MRRR
/// step: the tests pass one that fails (as dstemr may on clustered spectra, depending on
/// the machine) to check the fallback by construction rather than by a crafted matrix.
SymmetricEigen symmetricEigen(const Eigen::MatrixXd& S, TridiagonalEigenSolver tridiagonal = &mrrrTridiagonal);

/// The same by Eigen's SelfAdjointEigenSolver alone (the reference the tests compare with).
SymmetricEigen symmetricEigenByQr(const Eigen::MatrixXd& S);

}  // namespace mmv

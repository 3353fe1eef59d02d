#include "sim/core/symmetric_eigen.hpp"

#include <algorithm>
#include <vector>

#include "sim/core/errors.hpp"

extern "C" {
// LAPACK (liblapack3, reference): eigenpairs of a symmetric tridiagonal matrix by MRRR.
void dstemr_(const char* jobz, const char* range, const int* n, double* d, double* e, const double* vl,
             const double* vu, const int* il, const int* iu, int* m, double* w, double* z, const int* ldz,
             const int* nzc, int* isuppz, int* tryrac, double* work, const int* lwork, int* iwork, const int* liwork,
             int* info, std::size_t jobz_len, std::size_t range_len);
}

namespace mmv {

SymmetricEigen symmetricEigenByQr(const Eigen::MatrixXd& S) {
  if (!S.allFinite()) throw NumericalError("symmetric eigen solution: the matrix has non-finite entries");
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S, Eigen::ComputeEigenvectors);
  if (es.info() != Eigen::Success) throw NumericalError("symmetric eigen solution did not converge");
  return {es.eigenvalues(), es.eigenvectors(), false};
}

int mrrrTridiagonal(Eigen::VectorXd& d, Eigen::VectorXd& e, Eigen::VectorXd& values, Eigen::MatrixXd& Z, int& m) {
  const int ni = static_cast<int>(d.size()), lwork = 18 * ni, liwork = 10 * ni;
  int info = 0, tryrac = 1, il = 1, iu = ni;
  const double vl = 0, vu = 0;
  std::vector<int> isuppz(2 * static_cast<std::size_t>(ni)), iwork(static_cast<std::size_t>(liwork));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dstemr_("V", "A", &ni, d.data(), e.data(), &vl, &vu, &il, &iu, &m, values.data(), Z.data(), &ni, &ni,
          isuppz.data(), &tryrac, work.data(), &lwork, iwork.data(), &liwork, &info, 1, 1);
  return info;
}

SymmetricEigen symmetricEigen(const Eigen::MatrixXd& S, TridiagonalEigenSolver tridiagonal) {
  const Eigen::Index n = S.rows();
  if (n < kMrrrMinSize || n > 1 << 20) return symmetricEigenByQr(S);
  if (!S.allFinite()) throw NumericalError("symmetric eigen solution: the matrix has non-finite entries");
  // Scaled to a unit largest entry first, as Eigen's solver does (no overflow in the
  // reflectors); the eigenvalues are scaled back.
  const double scale = S.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return symmetricEigenByQr(S);
  const Eigen::Tridiagonalization<Eigen::MatrixXd> tri(S / scale);
  Eigen::VectorXd d = tri.diagonal(), e(n);
  e.head(n - 1) = tri.subDiagonal();
  e[n - 1] = 0;
  SymmetricEigen r;
  r.values.resize(n);
  Eigen::MatrixXd Z(n, n);
  int m = 0;
  const int info = tridiagonal(d, e, r.values, Z, m);
  // dstemr can fail where many eigenvalues are nearly equal (info 22, from its dlarrv;
  // whether it does depends on the machine and the LAPACK): Eigen's QR then, as for any
  // failure or non-finite result.
  if (info != 0 || m != n || !r.values.allFinite() || !Z.allFinite()) return symmetricEigenByQr(S);
  r.vectors = tri.matrixQ() * Z;
  r.values *= scale;
  r.by_mrrr = true;
  return r;
}

}  // namespace mmv

#include "sim/modes/tam.hpp"

#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {

const char* tamMethodName(TamMethod m) {
  switch (m) {
    case TamMethod::Guyan: return "guyan";
    case TamMethod::Irs: return "irs";
    case TamMethod::Serep: return "serep";
  }
  return "?";
}

bool parseTamMethod(const std::string& name, TamMethod& out) {
  if (name == "guyan" || name == "static") out = TamMethod::Guyan;
  else if (name == "irs") out = TamMethod::Irs;
  else if (name == "serep") out = TamMethod::Serep;
  else return false;
  return true;
}

namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

double hz(double omega2) { return std::sqrt(std::max(omega2, 0.0)) / (2 * M_PI); }

/// Guyan or IRS: coordinates = T readings, through x = [u_a; q_o] (see the header).
MatrixXd condensation(const TamInput& in, TamMethod method) {
  const Eigen::Index a = in.P.rows(), n = in.P.cols(), o = n - a;
  const Eigen::ColPivHouseholderQR<MatrixXd> qr(in.P);
  if (qr.rank() < a)
    throw NumericalError(strf("TAM (%s): the %ld sensor directions are dependent (rank %ld): two of them read the same "
                              "motion; drop one or move it",
                              tamMethodName(method), static_cast<long>(a), static_cast<long>(qr.rank())));
  const auto& perm = qr.colsPermutation().indices();
  MatrixXd PR(a, a), PO(a, o);
  for (Eigen::Index j = 0; j < a; ++j) PR.col(j) = in.P.col(perm[j]);
  for (Eigen::Index j = 0; j < o; ++j) PO.col(j) = in.P.col(perm[a + j]);
  const Eigen::PartialPivLU<MatrixXd> lu(PR);
  MatrixXd T0 = MatrixXd::Zero(n, n);  // q = T0 [u; q_o]
  const MatrixXd inv = lu.inverse();
  const MatrixXd coupling = o > 0 ? MatrixXd(-lu.solve(PO)) : MatrixXd(a, 0);  // Eigen's solve of an empty block is UB
  for (Eigen::Index j = 0; j < a; ++j) {
    T0.row(perm[j]).head(a) = inv.row(j);
    T0.row(perm[j]).tail(o) = coupling.row(j);
  }
  for (Eigen::Index j = 0; j < o; ++j) T0(perm[a + j], a + j) = 1;
  if (o == 0) return T0;
  const MatrixXd Mx = T0.transpose() * in.M * T0, Kx = T0.transpose() * in.K * T0;
  const MatrixXd Koo = Kx.bottomRightCorner(o, o);
  const Eigen::LLT<MatrixXd> koo(0.5 * (Koo + Koo.transpose()));
  if (koo.info() != Eigen::Success)
    throw NumericalError(strf("TAM (%s): the stiffness of the %ld coordinates the sensors leave out is singular or not "
                              "positive: a motion they do not see is unrestrained (a free joint, a mechanism); add a "
                              "sensor that sees it or use serep",
                              tamMethodName(method), static_cast<long>(o)));
  MatrixXd TG(n, a);
  TG.topRows(a) = MatrixXd::Identity(a, a);
  TG.bottomRows(o) = -koo.solve(Kx.bottomLeftCorner(o, a));
  if (method == TamMethod::Irs) {
    const MatrixXd MG = TG.transpose() * Mx * TG, KG = TG.transpose() * Kx * TG;
    const MatrixXd inertia = (Mx * TG).bottomRows(o);  // S M T_G, o-rows only
    TG.bottomRows(o) += koo.solve(inertia) * Eigen::LDLT<MatrixXd>(MG).solve(KG);
  }
  return T0 * TG;
}

MatrixXd serep(const TamInput& in) {
  const MatrixXd phi_a = in.P * in.phi;
  const Eigen::Index a = phi_a.rows(), m = phi_a.cols();
  if (a < m)  // a request that cannot be met, named by the option that asked for it
    throw OptionError("--tam", strf(" serep: %ld sensor directions for %ld target modes: SEREP needs at least as many "
                                    "directions as modes (raise --count or use --triaxial)",
                                    static_cast<long>(a), static_cast<long>(m)));
  const Eigen::CompleteOrthogonalDecomposition<MatrixXd> cod(phi_a);
  if (cod.rank() < m)
    throw NumericalError(strf("TAM (serep): the sensors cannot tell the %ld target modes apart (their shapes at the "
                              "sensors have rank %ld)",
                              static_cast<long>(m), static_cast<long>(cod.rank())));
  return in.phi * cod.pseudoInverse();
}

/// The TAM's own modes, on the range of M_tam (SEREP's M_tam has rank m).
void tamModes(TamResult& r) {
  const Eigen::SelfAdjointEigenSolver<MatrixXd> mass(r.M_tam);
  const double top = mass.eigenvalues().cwiseAbs().maxCoeff();
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < mass.eigenvalues().size(); ++i)
    if (mass.eigenvalues()[i] > 1e-10 * top) kept.push_back(i);
  MatrixXd U(r.M_tam.rows(), static_cast<Eigen::Index>(kept.size()));
  for (std::size_t i = 0; i < kept.size(); ++i) U.col(static_cast<Eigen::Index>(i)) = mass.eigenvectors().col(kept[i]);
  const MatrixXd Mr = U.transpose() * r.M_tam * U, Kr = U.transpose() * r.K_tam * U;
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatrixXd> g(0.5 * (Kr + Kr.transpose()), 0.5 * (Mr + Mr.transpose()));
  if (g.info() != Eigen::Success) throw NumericalError(std::string("TAM (") + tamMethodName(r.method) + "): its eigenproblem failed");
  r.tam_omega2 = g.eigenvalues();
  r.tam_shapes = U * g.eigenvectors();
}

void check(const TamInput& in, TamResult& r) {
  const MatrixXd phi_a = in.P * in.phi;
  const MatrixXd raw = phi_a.transpose() * r.M_tam * phi_a;
  const VectorXd d = raw.diagonal().cwiseMax(1e-300).cwiseSqrt();
  r.self = d.cwiseInverse().asDiagonal() * raw * d.cwiseInverse().asDiagonal();
  const MatrixXd unit = phi_a * d.cwiseInverse().asDiagonal();  // unit mass under M_tam
  r.cross = r.tam_shapes.transpose() * r.M_tam * unit;
  const Eigen::Index m = phi_a.cols();
  r.pass = true;
  for (Eigen::Index j = 0; j < m; ++j) {
    TamModeCheck c;
    Eigen::Index i = 0;
    c.cross_diagonal = r.cross.col(j).cwiseAbs().maxCoeff(&i);
    c.tam_mode = ModeNumber::atIndex(static_cast<int>(i));
    c.tam_frequency_hz = hz(r.tam_omega2[i]);
    c.frequency_error = c.tam_frequency_hz / hz(in.omega2[j]) - 1;
    c.self_diagonal = raw(j, j);
    for (Eigen::Index k = 0; k < m; ++k) {
      if (k == j) continue;
      c.self_off_diagonal = std::max(c.self_off_diagonal, std::abs(r.self(j, k)));
      c.cross_off_diagonal = std::max(c.cross_off_diagonal, std::abs(r.cross(i, k)));
    }
    if (c.self_off_diagonal > kTamOffDiagonalMax)
      c.reason = strf("self-orthogonality %.3f > %.1f", c.self_off_diagonal, kTamOffDiagonalMax);
    else if (c.cross_diagonal < kTamDiagonalMin)
      c.reason = strf("cross-orthogonality %.3f < %.1f", c.cross_diagonal, kTamDiagonalMin);
    else if (c.cross_off_diagonal > kTamOffDiagonalMax)
      c.reason = strf("cross-orthogonality off-diagonal %.3f > %.1f", c.cross_off_diagonal, kTamOffDiagonalMax);
    c.pass = c.reason.empty();
    r.pass = r.pass && c.pass;
    r.modes.push_back(c);
  }
}

}  // namespace

TamResult buildTam(const TamInput& in, TamMethod method) {
  const Eigen::Index n = in.M.rows();
  MMV_DEMAND(in.M.cols() == n && in.K.rows() == n && in.K.cols() == n && in.P.cols() == n && in.phi.rows() == n &&
             in.omega2.size() == in.phi.cols() && in.P.rows() >= 1);  // more rows than coordinates: dependent (named)
  TamResult r;
  r.method = method;
  r.sensors = static_cast<int>(in.P.rows());
  r.coordinates = static_cast<int>(n);
  r.T = method == TamMethod::Serep ? serep(in) : condensation(in, method);
  r.M_tam = r.T.transpose() * in.M * r.T;
  r.K_tam = r.T.transpose() * in.K * r.T;
  r.M_tam = 0.5 * (r.M_tam + r.M_tam.transpose()).eval();
  r.K_tam = 0.5 * (r.K_tam + r.K_tam.transpose()).eval();
  tamModes(r);
  check(in, r);
  return r;
}

}  // namespace mmv

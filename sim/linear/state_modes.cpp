// Modes of the state matrix for the modal reduction (state_modes.hpp).
#include "sim/linear/state_modes.hpp"

#include <Eigen/Eigenvalues>
#include <Spectra/GenEigsSolver.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "sim/core/errors.hpp"
#include "sim/core/linalg.hpp"

namespace mmv::detail {
namespace {

using cd = std::complex<double>;

bool isComplexMember(const cd& l) { return l.imag() > 1e-12 * std::abs(l); }

}  // namespace

Eigen::VectorXcd normalizeEigenvectors(Eigen::MatrixXcd& V) {
  const Eigen::Index N = V.rows();
  Eigen::VectorXcd scale(V.cols());
  Eigen::VectorXd r(N);
  for (Eigen::Index i = 0; i < N; ++i) r[i] = 1.0 + 0.5 * std::sin(1.6180339887 * double(i + 1));
  for (Eigen::Index j = 0; j < V.cols(); ++j) {
    cd s = r.cast<cd>().dot(V.col(j));  // (dot conjugates its first argument: r is real)
    if (!(std::abs(s) > 1e-6 * V.col(j).norm())) {
      Eigen::Index k = 0;
      V.col(j).cwiseAbs().maxCoeff(&k);
      s = V(k, j);
    }
    V.col(j) /= s;
    scale[j] = s;
  }
  return scale;
}

void collectModes(const StateSpace& full, StateEigen& sm, const std::vector<int>& indices) {
  sm.pair_max = Eigen::MatrixXd::Zero(full.C.rows(), full.B.cols());
  sm.modes.clear();
  const Eigen::MatrixXcd Cc = full.C.cast<cd>(), Bc = sm.Bt.cast<cd>();
  for (int i : indices) {
    const cd l = sm.lambda[i];
    if (l.imag() < -1e-12 * std::abs(l)) continue;
    const Eigen::VectorXd cv = (Cc * sm.V.col(i)).cwiseAbs();
    const Eigen::RowVectorXd wb = (sm.W.row(i) * Bc).cwiseAbs();
    const Eigen::MatrixXd res = cv * wb / std::max(std::abs(l), 1e-300);
    sm.pair_max = sm.pair_max.cwiseMax(res);
    sm.modes.push_back({i, isComplexMember(l), std::abs(l), res});
  }
}

StateEigen allStateModes(const StateSpace& full) {
  StateEigen sm;
  const Eigen::PartialPivLU<Eigen::MatrixXd> Elu(full.E);
  const Eigen::MatrixXd At = Elu.solve(full.A);
  sm.Bt = Elu.solve(full.B);
  Eigen::EigenSolver<Eigen::MatrixXd> es(At);
  if (es.info() != Eigen::Success) throw NumericalError("modal reduction: eigen solution of the state matrix failed");
  sm.lambda = es.eigenvalues();
  sm.V = es.eigenvectors();
  normalizeEigenvectors(sm.V);
  sm.W = sm.V.inverse();
  sm.times_state_matrix = [At](const Eigen::MatrixXd& X) -> Eigen::MatrixXd { return At * X; };
  const Eigen::MatrixXd A = full.A, B = full.B;
  sm.static_solution = [A, B]() -> std::optional<Eigen::MatrixXd> {
    const EquilibratedLu lu(A);
    if (!lu.isInvertible()) return std::nullopt;
    return lu.solve(B);
  };
  std::vector<int> all(full.numStates());
  for (int i = 0; i < full.numStates(); ++i) all[i] = i;
  collectModes(full, sm, all);
  return sm;
}

namespace {

/// M, C, K of a model built by secondOrderModel (E = diag(I, M), A = [0 I; -K -C]).
struct SecondOrderParts {
  Eigen::MatrixXd M, C, K;
};

bool symmetric(const Eigen::MatrixXd& X) {
  const double scale = X.cwiseAbs().maxCoeff();
  return (X - X.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * scale;
}

std::optional<SecondOrderParts> secondOrderParts(const StateSpace& s) {
  const Eigen::Index N = s.numStates(), n = N / 2;
  if (N == 0 || N % 2 || s.E.rows() != N) return std::nullopt;
  const bool form = s.E.topLeftCorner(n, n).isIdentity(0) && s.E.topRightCorner(n, n).isZero(0) &&
                    s.E.bottomLeftCorner(n, n).isZero(0) && s.A.topLeftCorner(n, n).isZero(0) &&
                    s.A.topRightCorner(n, n).isIdentity(0);
  if (!form) return std::nullopt;
  SecondOrderParts p{s.E.bottomRightCorner(n, n), -s.A.bottomRightCorner(n, n), -s.A.bottomLeftCorner(n, n)};
  if (!symmetric(p.M) || !symmetric(p.C) || !symmetric(p.K)) return std::nullopt;
  return p;
}

/// (E^-1 A)^-1 x for A = [0 I; -K -C], E = diag(I, M): y2 = x1, y1 = -K^-1 (C x1 + M x2);
/// with `deflate`, the computed modes are projected out before and after (P = I - V W).
class InverseStateMatrix {
 public:
  using Scalar = double;
  InverseStateMatrix(const SecondOrderParts& p, const EquilibratedLu& k) : p_(p), k_(k) {}
  Eigen::Index rows() const { return 2 * p_.K.rows(); }
  Eigen::Index cols() const { return rows(); }
  void deflate(const Eigen::MatrixXcd* V, const Eigen::MatrixXcd* W) { V_ = V, W_ = W; }
  void perform_op(const double* x_in, double* y_out) const {
    const Eigen::Index n = p_.K.rows();
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(x_in, 2 * n);
    project(x);
    Eigen::Map<Eigen::VectorXd> y(y_out, 2 * n);
    y.head(n) = -k_.solve(p_.C * x.head(n) + p_.M * x.tail(n));
    y.tail(n) = x.head(n);
    if (V_) {
      Eigen::VectorXd t = y;
      project(t);
      y = t;
    }
  }

 private:
  void project(Eigen::VectorXd& x) const {
    if (V_) x -= (*V_ * (*W_ * x.cast<cd>())).real();
  }
  const SecondOrderParts& p_;
  const EquilibratedLu& k_;
  const Eigen::MatrixXcd *V_ = nullptr, *W_ = nullptr;
};

/// Left eigenvectors from the right ones: for symmetric M, C, K the quadratic problem's
/// left vector is its right one phi, and the state matrix's is [-phi^T K / lambda, phi^T M],
/// scaled so w v = 1; then W := (W V)^-1 W, which separates close eigenvalues.
std::optional<Eigen::MatrixXcd> leftEigenvectors(const SecondOrderParts& p, const Eigen::VectorXcd& lambda,
                                                 const Eigen::MatrixXcd& V) {
  const Eigen::Index n = p.K.rows(), k = V.cols();
  Eigen::MatrixXcd W(k, 2 * n);
  for (Eigen::Index j = 0; j < k; ++j) {
    const Eigen::VectorXcd phi = V.col(j).head(n);
    W.row(j).head(n) = -(p.K * phi).transpose() / lambda[j];
    W.row(j).tail(n) = (p.M * phi).transpose();
    const cd s = W.row(j) * V.col(j);
    if (!(std::abs(s) > 1e-8 * W.row(j).norm() * V.col(j).norm())) return std::nullopt;  // (near) defective
    W.row(j) /= s;
  }
  // G = I for distinct eigenvalues; within a repeated one, any invertible block.
  const Eigen::MatrixXcd G = W * V;
  const Eigen::PartialPivLU<Eigen::MatrixXcd> glu(G);
  if (!(glu.rcond() > 1e-8)) return std::nullopt;  // two Ritz vectors for one direction
  return Eigen::MatrixXcd(glu.solve(W));
}

/// Whether every computed pair solves the quadratic problem to a relative residual of 1e-9.
bool residualsSmall(const SecondOrderParts& p, const Eigen::VectorXcd& lambda, const Eigen::MatrixXcd& V) {
  const Eigen::Index n = p.K.rows();
  const double m = p.M.cwiseAbs().rowwise().sum().maxCoeff(), c = p.C.cwiseAbs().rowwise().sum().maxCoeff(),
               kk = p.K.cwiseAbs().rowwise().sum().maxCoeff();
  for (Eigen::Index j = 0; j < V.cols(); ++j) {
    const cd l = lambda[j];
    const Eigen::VectorXcd phi = V.col(j).head(n);
    const Eigen::VectorXcd r = l * l * (p.M * phi) + l * (p.C * phi) + p.K * phi;
    const double scale = (std::norm(l) * m + std::abs(l) * c + kk) * phi.cwiseAbs().maxCoeff();
    if (!(r.cwiseAbs().maxCoeff() <= 1e-9 * scale)) return false;
  }
  return true;
}

}  // namespace

namespace {

/// The Arnoldi run's Ritz pairs as modes: real roots and the pairs' upper members, then
/// the conjugates (so V W is real); nullopt when fewer than `pairs` pairs are among them.
std::optional<StateEigen> ritzModes(const Eigen::VectorXcd& mu, const Eigen::MatrixXcd& X, int pairs) {
  std::vector<int> upper;
  int found = 0;
  for (int i = 0; i < int(mu.size()); ++i) {
    const cd l = 1.0 / mu[i];
    if (l.imag() < -1e-12 * std::abs(l)) continue;
    upper.push_back(i);
    found += isComplexMember(l);
  }
  if (found < pairs) return std::nullopt;
  StateEigen sm;
  sm.lambda.resize(upper.size() + found);
  sm.V.resize(X.rows(), upper.size() + found);
  int col = 0;
  for (int i : upper) sm.lambda[col] = 1.0 / mu[i], sm.V.col(col++) = X.col(i);
  for (int i : upper)
    if (isComplexMember(1.0 / mu[i])) sm.lambda[col] = std::conj(1.0 / mu[i]), sm.V.col(col++) = X.col(i).conjugate();
  return sm;
}

/// The modes' indices by increasing magnitude, and the magnitude of the pairs-th pair.
std::pair<std::vector<int>, double> orderAndReach(const Eigen::VectorXcd& lambda, int pairs) {
  std::vector<int> order(lambda.size());
  for (int i = 0; i < int(order.size()); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return std::abs(lambda[a]) < std::abs(lambda[b]); });
  int counted = 0;
  for (int i : order)
    if (isComplexMember(lambda[i]) && ++counted == pairs) return {order, std::abs(lambda[i])};
  return {order, 0.0};
}

/// Whether no mode outside those computed lies at or below `reach`: the deflated
/// operator's largest eigenvalue must be smaller than 1 / reach by 0.1 % (a mode the
/// first run missed, such as the second copy of a repeated eigenvalue, would be the
/// largest). Converged to 1e-4 only: a cluster of overdamped roots there (hundreds within
/// 1e-5 of each other) converges to its width, and a mode as close as 0.1 % to the kept
/// ones sends the reduction to the dense solver.
bool noneMissedBelow(InverseStateMatrix& op, const StateEigen& sm, double reach) {
  op.deflate(&sm.V, &sm.W);
  Spectra::GenEigsSolver<InverseStateMatrix> check(op, 2, std::min<Eigen::Index>(op.rows(), 30));
  check.init();
  check.compute(Spectra::SortRule::LargestMagn, 300, 1e-4);
  op.deflate(nullptr, nullptr);
  return check.info() == Spectra::CompInfo::Successful &&
         1.0 / check.eigenvalues().cwiseAbs().maxCoeff() > reach * (1 + 1e-3);
}

/// E^-1 B, E^-1 A X and A^-1 B from the second-order blocks. The two closures share one
/// copy of the blocks and factors (each held its own: four n x n copies at 64 segments a
/// link, 3 % of `rom`).
void structuredProducts(const StateSpace& full, const SecondOrderParts& p, const EquilibratedLu& klu, StateEigen& sm) {
  struct Held {
    SecondOrderParts p;
    Eigen::PartialPivLU<Eigen::MatrixXd> mlu;
    EquilibratedLu klu;
    Eigen::MatrixXd B;
  };
  const auto h = std::make_shared<const Held>(Held{p, Eigen::PartialPivLU<Eigen::MatrixXd>(p.M), klu, full.B});
  const Eigen::Index n = p.K.rows();
  sm.Bt = full.B;
  sm.Bt.bottomRows(n) = h->mlu.solve(full.B.bottomRows(n));
  sm.times_state_matrix = [h, n](const Eigen::MatrixXd& X) -> Eigen::MatrixXd {
    Eigen::MatrixXd Y(X.rows(), X.cols());
    Y.topRows(n) = X.bottomRows(n);
    Y.bottomRows(n) = -h->mlu.solve(h->p.K * X.topRows(n) + h->p.C * X.bottomRows(n));
    return Y;
  };
  sm.static_solution = [h, n]() -> std::optional<Eigen::MatrixXd> {
    const Eigen::MatrixXd& B = h->B;
    Eigen::MatrixXd X(B.rows(), B.cols());  // A X = B: X2 = B1, -K X1 - C X2 = B2
    X.bottomRows(n) = B.topRows(n);
    X.topRows(n) = -h->klu.solve(B.bottomRows(n) + h->p.C * B.topRows(n));
    return X;
  };
}

}  // namespace

std::optional<StateEigen> lowestStateModes(const StateSpace& full, int pairs, std::string* declined,
                                           const Eigen::VectorXd* start) {
  const auto decline = [&](const char* why) -> std::optional<StateEigen> {
    if (declined) *declined = why;
    return std::nullopt;
  };
  const std::optional<SecondOrderParts> parts = secondOrderParts(full);
  if (!parts) return decline("not the first-order form of a second-order model with symmetric M, C, K");
  if (pairs < 1) return decline("no mode count");
  const Eigen::Index N = full.numStates();
  const EquilibratedLu klu(parts->K);
  if (!klu.isInvertible()) return decline("K is singular (a rigid-body mode)");
  InverseStateMatrix op(*parts, klu);
  // nev = 2 pairs first: the cut then falls between the pairs-th pair and the next mode,
  // not inside a cluster further out (the hinge dampers' overdamped roots crowd at
  // -1/beta, hundreds of them); real roots below the cut raise it.
  for (Eigen::Index nev = 2 * pairs; nev + 2 <= N / 2;) {
    const Eigen::Index ncv = std::min<Eigen::Index>(N, std::max<Eigen::Index>(2 * nev + 1, nev + 20));
    Spectra::GenEigsSolver<InverseStateMatrix> eigs(op, nev, ncv);
    if (start)
      eigs.init(start->data());
    else
      eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, 1000, 1e-12);
    if (eigs.info() != Spectra::CompInfo::Successful) return decline("Arnoldi did not converge");
    std::optional<StateEigen> sm = ritzModes(eigs.eigenvalues(), eigs.eigenvectors(), pairs);
    if (!sm) {  // real roots below the pairs-th pair
      nev += std::max<Eigen::Index>(2, nev / 4);
      continue;
    }
    const auto [order, reach] = orderAndReach(sm->lambda, pairs);
    normalizeEigenvectors(sm->V);
    if (!residualsSmall(*parts, sm->lambda, sm->V)) return decline("a Ritz pair's residual is above 1e-9");
    const std::optional<Eigen::MatrixXcd> W = leftEigenvectors(*parts, sm->lambda, sm->V);
    if (!W) return decline("left and right eigenvectors are not biorthogonal (a defective mode)");
    sm->W = *W;
    if (!noneMissedBelow(op, *sm, reach)) return decline("the deflated operator has a mode as low as the kept ones");
    structuredProducts(full, *parts, klu, *sm);
    sm->every_mode = false;
    collectModes(full, *sm, order);
    return sm;
  }
  return decline("the modes needed are more than a quarter of the model's");
}

namespace {

/// One root of lambda^2 + c lambda + omega^2 = 0 of undamped mode `mode` (a pair's upper member).
struct ModalRoot {
  Eigen::Index mode;
  cd lambda;
};

/// Each undamped mode's roots (a pair's upper member, or two real ones), by magnitude;
/// an empty `why` when every mode is stiff and not critically damped.
std::vector<ModalRoot> modalRoots(const ProportionalModes& b, std::string& why) {
  std::vector<ModalRoot> roots;
  for (Eigen::Index k = 0; k < b.omega2.size(); ++k) {
    const double w2 = b.omega2[k], c = b.c[k], disc = c * c - 4 * w2;
    if (!(w2 > 0) || !std::isfinite(c)) return why = "a mode of zero or negative stiffness (K is singular or indefinite)", roots;
    if (std::abs(disc) <= 1e-8 * (c * c + 4 * w2)) return why = "a critically damped mode (a defective eigenvalue)", roots;
    if (disc < 0) {
      roots.push_back({k, cd(-c / 2, std::sqrt(-disc) / 2)});
    } else {  // overdamped: the larger root without cancellation, the smaller from the product
      const double q = -(c + std::sqrt(disc)) / 2;
      roots.push_back({k, q});
      roots.push_back({k, w2 / q});
    }
  }
  std::stable_sort(roots.begin(), roots.end(), [](const ModalRoot& a, const ModalRoot& b) { return std::abs(a.lambda) < std::abs(b.lambda); });
  return roots;
}

/// Whether the modes solve the model: K phi = omega^2 M phi and C phi = c M phi, each to a
/// residual on the quadratic problem of 1e-9 of its scale (residualsSmall's).
bool proportionalResidualsSmall(const SecondOrderParts& p, const ProportionalModes& b, const std::vector<ModalRoot>& roots) {
  const double m = p.M.cwiseAbs().rowwise().sum().maxCoeff(), c = p.C.cwiseAbs().rowwise().sum().maxCoeff(),
               kk = p.K.cwiseAbs().rowwise().sum().maxCoeff();
  std::vector<Eigen::Index> used;
  for (const ModalRoot& r : roots) used.push_back(r.mode);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  const Eigen::MatrixXd phi = b.shapes(Eigen::all, used);
  const Eigen::MatrixXd Mphi = p.M * phi;
  const Eigen::VectorXd w2 = b.omega2(used), cm = b.c(used);
  const Eigen::VectorXd ek = (p.K * phi - Mphi * w2.asDiagonal()).cwiseAbs().colwise().maxCoeff();
  const Eigen::VectorXd ec = (p.C * phi - Mphi * cm.asDiagonal()).cwiseAbs().colwise().maxCoeff();
  for (const ModalRoot& r : roots) {
    const auto j = std::lower_bound(used.begin(), used.end(), r.mode) - used.begin();
    const double l = std::abs(r.lambda);
    const double scale = (l * l * m + l * c + kk) * phi.col(j).cwiseAbs().maxCoeff();
    if (!(l * ec[j] + ek[j] <= 1e-9 * scale)) return false;
  }
  return true;
}

/// Largest |X| entry.
double largest(const Eigen::MatrixXd& X) { return X.size() ? X.cwiseAbs().maxCoeff() : 0.0; }

/// structuredProducts from the modes, no factorization: M^-1 = Phi Phi^T and
/// K^-1 = Phi diag(1 / omega^2) Phi^T (Phi^T M Phi = I, Phi^T K Phi = diag(omega^2)), each
/// O(n^2) per column applied to. The residual check on the used modes does not see the
/// others, which these inverses use too, so each is checked where it is applied: E^-1 B
/// on M (false when it fails: the solvers then take over), A^-1 B on K and C (a
/// factorization of K instead when it fails).
bool modalProducts(const StateSpace& full, SecondOrderParts p, std::shared_ptr<const ProportionalModes> modes, StateEigen& sm) {
  struct Held {
    Eigen::MatrixXd C, K, B;
    std::shared_ptr<const ProportionalModes> modes;
  };
  const Eigen::MatrixXd& phi = modes->shapes;
  const Eigen::Index n = phi.rows();
  sm.Bt = full.B;
  sm.Bt.bottomRows(n) = phi * (phi.transpose() * full.B.bottomRows(n));
  const double m = p.M.cwiseAbs().rowwise().sum().maxCoeff();
  if (!(largest(p.M * sm.Bt.bottomRows(n) - full.B.bottomRows(n)) <= 1e-9 * (m * largest(sm.Bt.bottomRows(n)) + 1e-300)))
    return false;
  const auto h = std::make_shared<const Held>(Held{std::move(p.C), std::move(p.K), full.B, std::move(modes)});
  sm.times_state_matrix = [h, n](const Eigen::MatrixXd& X) -> Eigen::MatrixXd {
    const Eigen::MatrixXd& phi = h->modes->shapes;
    Eigen::MatrixXd Y(X.rows(), X.cols());
    Y.topRows(n) = X.bottomRows(n);
    Y.bottomRows(n) = -phi * (phi.transpose() * (h->K * X.topRows(n) + h->C * X.bottomRows(n)));
    return Y;
  };
  sm.static_solution = [h, n]() -> std::optional<Eigen::MatrixXd> {
    const Eigen::MatrixXd& phi = h->modes->shapes;
    const Eigen::MatrixXd& B = h->B;
    Eigen::MatrixXd X(B.rows(), B.cols());  // A X = B: X2 = B1, -K X1 - C X2 = B2
    X.bottomRows(n) = B.topRows(n);
    const Eigen::MatrixXd rhs = B.bottomRows(n) + h->C * B.topRows(n);
    X.topRows(n) = -phi * (h->modes->omega2.cwiseInverse().asDiagonal() * (phi.transpose() * rhs));
    const double k = h->K.cwiseAbs().rowwise().sum().maxCoeff();
    if (largest(h->K * X.topRows(n) + rhs) <= 1e-9 * (k * largest(X.topRows(n)) + 1e-300)) return X;
    const EquilibratedLu klu(h->K);
    if (!klu.isInvertible()) return std::nullopt;
    X.topRows(n) = -klu.solve(rhs);
    return X;
  };
  return true;
}

}  // namespace

std::optional<StateEigen> proportionalStateModes(const StateSpace& full, std::shared_ptr<const ProportionalModes> modes,
                                                 int pairs, std::string* declined) {
  MMV_DEMAND(modes != nullptr);
  const ProportionalModes& b = *modes;
  const auto decline = [&](const std::string& why) -> std::optional<StateEigen> {
    if (declined) *declined = why;
    return std::nullopt;
  };
  const std::optional<SecondOrderParts> parts = secondOrderParts(full);
  if (!parts) return decline("not the first-order form of a second-order model with symmetric M, C, K");
  const Eigen::Index n = parts->K.rows();
  if (b.shapes.rows() != n || b.shapes.cols() != n || b.omega2.size() != n || b.c.size() != n)
    return decline("the proportional modes are not of this model's size");
  std::string why;
  std::vector<ModalRoot> roots = modalRoots(b, why);
  if (!why.empty()) return decline(why);
  // The lowest `pairs` pairs and every root no larger than the last of them (what the
  // reduction keeps, selectModes), or every root.
  std::size_t count = roots.size();
  for (std::size_t i = 0, seen = 0; pairs > 0 && i < roots.size(); ++i)
    if (isComplexMember(roots[i].lambda) && ++seen == static_cast<std::size_t>(pairs)) {
      const double reach = std::abs(roots[i].lambda);
      for (count = i + 1; count < roots.size() && std::abs(roots[count].lambda) <= reach;) ++count;
      break;
    }
  const bool every_mode = count == roots.size();
  roots.resize(count);
  if (!proportionalResidualsSmall(*parts, b, roots)) return decline("the proportional modes do not solve this model's M, C, K");
  // v = [phi; lambda phi]; w = [-(omega^2 / lambda) phi^T M, phi^T M] / (lambda - omega^2 / lambda)
  // (phi^T K = omega^2 phi^T M), so w v = 1 and, by the modes' M- and K-orthogonality,
  // w_i v_j = 0 for i != j (a pair's two roots too: their product is omega^2).
  Eigen::Index pairs_found = 0;
  for (const ModalRoot& r : roots) pairs_found += isComplexMember(r.lambda);
  const Eigen::Index cols = static_cast<Eigen::Index>(roots.size()) + pairs_found;
  StateEigen sm;
  sm.lambda.resize(cols);
  sm.V.resize(2 * n, cols);
  sm.W.resize(cols, 2 * n);
  Eigen::Index col = 0;
  const auto add = [&](Eigen::Index k, const cd& l) {
    const Eigen::VectorXd& phi = b.shapes.col(k);
    const Eigen::RowVectorXd phiM = (parts->M * phi).transpose();
    const double w2 = b.omega2[k];
    sm.lambda[col] = l;
    sm.V.col(col).head(n) = phi.cast<cd>();
    sm.V.col(col).tail(n) = l * phi.cast<cd>();
    const cd s = l - w2 / l;
    sm.W.row(col).head(n) = (-(w2 / l) / s) * phiM.cast<cd>();
    sm.W.row(col).tail(n) = (1.0 / s) * phiM.cast<cd>();
    ++col;
  };
  for (const ModalRoot& r : roots) add(r.mode, r.lambda);
  for (const ModalRoot& r : roots)
    if (isComplexMember(r.lambda)) add(r.mode, std::conj(r.lambda));
  const Eigen::VectorXcd scale = normalizeEigenvectors(sm.V);
  sm.W = scale.asDiagonal() * sm.W;
  if (!modalProducts(full, std::move(*parts), modes, sm))
    return decline("the proportional modes do not invert this model's M (a mode outside those kept is not M-orthonormal)");
  sm.every_mode = every_mode;
  std::vector<int> order(roots.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  collectModes(full, sm, order);
  return sm;
}

}  // namespace mmv::detail

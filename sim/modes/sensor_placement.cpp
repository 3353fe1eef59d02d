#include "sim/modes/sensor_placement.hpp"
#include "sim/core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "sim/core/errors.hpp"

namespace mmv {

bool parsePlacementMethod(const std::string& name, PlacementMethod& method) {
  if (name == "efi") method = PlacementMethod::EffectiveIndependence;
  else if (name == "mke") method = PlacementMethod::ModalKineticEnergy;
  else if (name == "dpr") method = PlacementMethod::DrivingPointResidue;
  else return false;
  return true;
}

const char* placementMethodName(PlacementMethod m) {
  switch (m) {
    case PlacementMethod::EffectiveIndependence: return "effective independence";
    case PlacementMethod::ModalKineticEnergy: return "modal kinetic energy";
    case PlacementMethod::DrivingPointResidue: return "driving-point residue";
  }
  return "";
}

Eigen::MatrixXd autoMac(const Eigen::MatrixXd& phi) {
  const Eigen::Index k = phi.cols();
  Eigen::MatrixXd mac(k, k);
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j) {
      const double d = phi.col(i).squaredNorm() * phi.col(j).squaredNorm();
      mac(i, j) = d > 0 ? std::pow(phi.col(i).dot(phi.col(j)), 2) / d : 0.0;
    }
  return mac;
}

Eigen::MatrixXd rowsOfBlocks(const PlacementProblem& p, const std::vector<int>& blocks) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = 0; r < p.phi.rows(); ++r)
    if (std::find(blocks.begin(), blocks.end(), p.block[r]) != blocks.end()) rows.push_back(r);
  Eigen::MatrixXd out(rows.size(), p.phi.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) out.row(i) = p.phi.row(rows[i]);
  return out;
}

namespace {

int blockCount(const PlacementProblem& p) {
  return p.block.empty() ? 0 : *std::max_element(p.block.begin(), p.block.end()) + 1;
}

/// Rows of each block.
std::vector<std::vector<Eigen::Index>> blockRows(const PlacementProblem& p) {
  std::vector<std::vector<Eigen::Index>> rows(blockCount(p));
  for (Eigen::Index r = 0; r < p.phi.rows(); ++r) rows[p.block[r]].push_back(r);
  return rows;
}

/// Iterative deletion: returns the kept blocks and fills the deletion order and the
/// kept blocks' EfI values.
std::vector<int> effectiveIndependence(const PlacementProblem& p, int count, PlacementResult& r) {
  const auto rows = blockRows(p);
  std::vector<int> kept(rows.size());
  std::iota(kept.begin(), kept.end(), 0);
  auto projector = [&](const std::vector<int>& blocks, Eigen::MatrixXd& Qinv) {
    const Eigen::MatrixXd A = rowsOfBlocks(p, blocks);
    const Eigen::MatrixXd Q = A.transpose() * A;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Q);
    if (!lu.isInvertible())
      throw NumericalError("sensor placement: the candidates cannot tell every target mode apart (Fisher information singular)");
    Qinv = lu.inverse();
  };
  Eigen::MatrixXd Qinv;
  projector(kept, Qinv);
  const ProgressStage stage("effective independence: deleting candidates");
  const long to_delete = static_cast<long>(kept.size()) - count;
  while (static_cast<int>(kept.size()) > count) {
    progressCount(to_delete - (static_cast<long>(kept.size()) - count) + 1, to_delete, "deletion");
    double best = -1;
    std::size_t best_i = 0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const auto& rb = rows[kept[i]];
      Eigen::MatrixXd B(rb.size(), p.phi.cols());
      for (std::size_t j = 0; j < rb.size(); ++j) B.row(j) = p.phi.row(rb[j]);
      const Eigen::MatrixXd E = B * Qinv * B.transpose();
      const double keep = (Eigen::MatrixXd::Identity(rb.size(), rb.size()) - E).determinant();  // det(Q') / det(Q)
      if (keep > best) best = keep, best_i = i;
    }
    r.deletion_order.push_back(kept[best_i]);
    kept.erase(kept.begin() + static_cast<long>(best_i));
    projector(kept, Qinv);
  }
  r.block_score.resize(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    double e = 0;
    for (Eigen::Index row : rows[kept[i]]) e += p.phi.row(row) * Qinv * p.phi.row(row).transpose();
    r.block_score[i] = e;
  }
  return kept;
}

/// Ranking by a per-row score: the `count` blocks with the largest sums.
std::vector<int> ranking(const PlacementProblem& p, const Eigen::VectorXd& row_score, int count, PlacementResult& r) {
  const auto rows = blockRows(p);
  std::vector<double> score(rows.size(), 0.0);
  for (std::size_t b = 0; b < rows.size(); ++b)
    for (Eigen::Index row : rows[b]) score[b] += row_score[row];
  std::vector<int> order(rows.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return score[a] > score[b]; });
  std::vector<int> kept(order.begin(), order.begin() + count);
  std::sort(kept.begin(), kept.end());
  r.block_score.resize(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) r.block_score[i] = score[kept[i]];
  return kept;
}

}  // namespace

PlacementResult placeSensors(const PlacementProblem& p, PlacementMethod method, int count) {
  const int blocks = blockCount(p);
  MMV_DEMAND(static_cast<Eigen::Index>(p.block.size()) == p.phi.rows());
  MMV_DEMAND(count >= 1 && count <= blocks);  // the CLI checks --count against the candidates
  PlacementResult r;
  const Eigen::Index k = p.phi.cols();
  if (method == PlacementMethod::EffectiveIndependence) {
    r.kept_blocks = effectiveIndependence(p, count, r);
  } else if (method == PlacementMethod::ModalKineticEnergy) {
    MMV_DEMAND(p.row_mass.size() == p.phi.rows());
    r.kept_blocks = ranking(p, p.row_mass.cwiseProduct(p.phi.rowwise().squaredNorm()), count, r);
  } else {
    MMV_DEMAND(p.omega.size() == k && (p.omega.array() > 0).all());
    const Eigen::VectorXd w = p.omega.cwiseInverse();
    r.kept_blocks = ranking(p, p.phi.cwiseAbs2() * w, count, r);
  }
  const Eigen::MatrixXd A = rowsOfBlocks(p, r.kept_blocks);
  const Eigen::MatrixXd Q = A.transpose() * A;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Q);
  const Eigen::VectorXd sv = svd.singularValues();
  // Q is positive semi-definite: beyond 1e14 its smallest singular value is round-off,
  // so it is singular (determinant 0, condition infinite), never a tiny negative number.
  const bool singular = !sv.size() || !(sv[sv.size() - 1] > 1e-14 * sv[0]);
  r.fisher_condition = singular ? std::numeric_limits<double>::infinity() : sv[0] / sv[sv.size() - 1];
  r.fisher_determinant = singular ? 0.0 : sv.prod();
  r.automac = autoMac(A);
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j)
      if (i != j) r.max_offdiagonal_mac = std::max(r.max_offdiagonal_mac, r.automac(i, j));
  return r;
}

}  // namespace mmv

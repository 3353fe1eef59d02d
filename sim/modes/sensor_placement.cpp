#include "sim/modes/sensor_placement.hpp"
#include "sim/core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

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

/// Pairs of blocks too close to be kept together (apart, closer than the separation).
std::vector<std::vector<int>> conflicts(const PlacementProblem& p) {
  std::vector<std::vector<int>> out(p.block_at.size());
  if (p.min_separation <= 0) return out;
  for (std::size_t a = 0; a < p.block_at.size(); ++a)
    for (std::size_t b = a + 1; b < p.block_at.size(); ++b) {
      const double d = (p.block_at[a] - p.block_at[b]).norm();
      if (p.fixed(static_cast<int>(a)) && p.fixed(static_cast<int>(b))) continue;  // both the user's: as they are
      if (d > 1e-9 && d < p.min_separation) out[a].push_back(static_cast<int>(b)), out[b].push_back(static_cast<int>(a));
    }
  return out;
}

/// Iterative deletion: returns the kept blocks and fills the deletion order and the
/// kept blocks' EfI values. With a minimum separation, while two kept blocks are too
/// close the deletion chooses among those in conflict (the one whose loss costs the
/// least information), so the kept set ends with none; it may then hold fewer than
/// `count` blocks (the separation leaves no more), and never fewer rows than modes.
std::vector<int> effectiveIndependence(const PlacementProblem& p, int count, PlacementResult& r) {
  const auto rows = blockRows(p);
  const auto near = conflicts(p);
  std::vector<int> kept(rows.size()), clashes(rows.size(), 0);  // clashes: kept blocks too close to this one
  std::iota(kept.begin(), kept.end(), 0);
  for (std::size_t b = 0; b < near.size(); ++b) clashes[b] = static_cast<int>(near[b].size());
  auto projector = [&](const std::vector<int>& blocks, Eigen::MatrixXd& Qinv) {
    const Eigen::MatrixXd A = rowsOfBlocks(p, blocks);
    const Eigen::MatrixXd Q = A.transpose() * A;
    Eigen::FullPivLU<Eigen::MatrixXd> lu(Q);
    if (!lu.isInvertible())
      throw NumericalError("sensor placement: the candidates cannot tell every target mode apart (Fisher information singular)");
    Qinv = lu.inverse();
  };
  auto clashing = [&] { return std::any_of(kept.begin(), kept.end(), [&](int b) { return clashes[static_cast<std::size_t>(b)] > 0; }); };
  Eigen::MatrixXd Qinv;
  projector(kept, Qinv);
  const ProgressStage stage("effective independence: deleting candidates");
  const long to_delete = static_cast<long>(kept.size()) - count;
  while (static_cast<int>(kept.size()) > count || (!near.empty() && clashing())) {
    progressCount(std::min(to_delete, to_delete - (static_cast<long>(kept.size()) - count) + 1), to_delete, "deletion");
    // Resolving the separation: the block in the most conflicts goes first (removing a
    // crowded station frees its neighbours; by information alone the deletion eats a
    // chain of close stations from one end and frees none), the least informative of them.
    const bool separate = !near.empty() && clashing();
    double best = -1;
    int most = 0;
    std::size_t best_i = 0;
    bool found = false;
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if (p.fixed(kept[i])) continue;  // fixed in advance: never deleted
      const int c = separate ? clashes[static_cast<std::size_t>(kept[i])] : 0;
      if (separate && (c == 0 || c < most)) continue;
      const auto& rb = rows[kept[i]];
      Eigen::MatrixXd B(rb.size(), p.phi.cols());
      for (std::size_t j = 0; j < rb.size(); ++j) B.row(j) = p.phi.row(rb[j]);
      const Eigen::MatrixXd E = B * Qinv * B.transpose();
      const double keep = (Eigen::MatrixXd::Identity(rb.size(), rb.size()) - E).determinant();  // det(Q') / det(Q)
      if (c > most || keep > best) best = keep, best_i = i, most = c, found = true;
    }
    MMV_DEMAND(found);  // count >= the fixed blocks, and a fixed pair never clashes
    const int gone = kept[best_i];
    Eigen::Index left = 0;
    for (int b : kept) left += b == gone ? 0 : static_cast<Eigen::Index>(rows[static_cast<std::size_t>(b)].size());
    if (left < p.phi.cols())
      throw OptionError("--min-separation", strf(" %g m: the candidates it leaves cannot tell every target mode apart (%ld "
                                                 "measured directions for %ld modes); lower it or place more densely",
                                                 p.min_separation, static_cast<long>(left), static_cast<long>(p.phi.cols())));
    if (!near.empty())
      for (int n : near[static_cast<std::size_t>(gone)]) --clashes[static_cast<std::size_t>(n)];
    r.deletion_order.push_back(gone);
    kept.erase(kept.begin() + static_cast<long>(best_i));
    try {
      projector(kept, Qinv);
    } catch (const NumericalError&) {
      if (!separate) throw;
      throw OptionError("--min-separation", strf(" %g m: the candidates it leaves cannot tell every target mode apart "
                                                 "(Fisher information singular); lower it or place more densely",
                                                 p.min_separation));
    }
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
  // In score order, each block kept unless it is too close to one kept before it.
  const auto near = conflicts(p);
  std::vector<int> kept;
  std::vector<char> taken(rows.size(), 0);
  for (int b = 0; b < static_cast<int>(rows.size()); ++b)  // the fixed ones first, whatever their score
    if (p.fixed(b)) kept.push_back(b), taken[static_cast<std::size_t>(b)] = 1;
  for (int b : order) {
    if (taken[static_cast<std::size_t>(b)]) continue;
    if (static_cast<int>(kept.size()) == count) break;
    if (!near.empty() && std::any_of(near[static_cast<std::size_t>(b)].begin(), near[static_cast<std::size_t>(b)].end(),
                                     [&](int n) { return taken[static_cast<std::size_t>(n)] != 0; }))
      continue;
    kept.push_back(b);
    taken[static_cast<std::size_t>(b)] = 1;
  }
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
  MMV_DEMAND(count >= static_cast<int>(std::count(p.fixed_block.begin(), p.fixed_block.end(), 1)));
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

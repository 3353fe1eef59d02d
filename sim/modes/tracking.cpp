#include "sim/modes/tracking.hpp"

#include <limits>

#include "sim/core/errors.hpp"
#include "sim/modes/cms.hpp"

namespace mmv {

std::vector<int> optimalAssignment(const Eigen::MatrixXd& cost) {
  // The Hungarian method with potentials (Kuhn-Munkres, O(n^2 m)), rows n <= columns m:
  // rows are added one at a time; each finds the cheapest augmenting path through the
  // reduced costs cost(i, j) - u(i) - v(j) >= 0, keeping the potentials feasible.
  const int n = static_cast<int>(cost.rows()), m = static_cast<int>(cost.cols());
  MMV_DEMAND(n <= m);
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> row_of(m + 1, 0), way(m + 1, 0);  // 1-based; row_of[0] is the row being added
  for (int i = 1; i <= n; ++i) {
    row_of[0] = i;
    int j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<bool> used(m + 1, false);
    do {
      used[j0] = true;
      const int i0 = row_of[j0];
      double delta = inf;
      int j1 = 0;
      for (int j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = cost(i0 - 1, j - 1) - u[i0] - v[j];
        if (cur < minv[j]) minv[j] = cur, way[j] = j0;
        if (minv[j] < delta) delta = minv[j], j1 = j;
      }
      for (int j = 0; j <= m; ++j) {
        if (used[j]) u[row_of[j]] += delta, v[j] -= delta;
        else minv[j] -= delta;
      }
      j0 = j1;
    } while (row_of[j0] != 0);
    do {  // augment along the path
      const int j1 = way[j0];
      row_of[j0] = row_of[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> out(n, -1);
  for (int j = 1; j <= m; ++j)
    if (row_of[j] > 0) out[row_of[j] - 1] = j - 1;
  return out;
}

ModeMatch matchModes(const Eigen::MatrixXd& previous, const Eigen::MatrixXd& current) {
  MMV_DEMAND(current.cols() >= previous.cols());  // at least as many current modes as tracked ones
  const Eigen::MatrixXd mac = modalAssuranceCriterion(previous, current);
  ModeMatch m;
  m.index = optimalAssignment(Eigen::MatrixXd::Ones(mac.rows(), mac.cols()) - mac);
  for (std::size_t i = 0; i < m.index.size(); ++i) m.mac.push_back(mac(static_cast<Eigen::Index>(i), m.index[i]));
  return m;
}

}  // namespace mmv

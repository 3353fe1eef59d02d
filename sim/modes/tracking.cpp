#include "sim/modes/tracking.hpp"

#include "sim/core/errors.hpp"
#include <algorithm>
#include <stdexcept>
#include <tuple>

#include "sim/modes/cms.hpp"

namespace mmv {

ModeMatch matchModes(const Eigen::MatrixXd& previous, const Eigen::MatrixXd& current) {
  MMV_DEMAND(current.cols() >= previous.cols());  // at least as many current modes as tracked ones
  const Eigen::MatrixXd mac = modalAssuranceCriterion(previous, current);
  std::vector<std::tuple<double, int, int>> pairs;
  for (Eigen::Index i = 0; i < mac.rows(); ++i)
    for (Eigen::Index j = 0; j < mac.cols(); ++j) pairs.emplace_back(mac(i, j), static_cast<int>(i), static_cast<int>(j));
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return std::get<0>(a) > std::get<0>(b); });
  ModeMatch m;
  m.index.assign(previous.cols(), -1);
  m.mac.assign(previous.cols(), 0.0);
  std::vector<bool> used(current.cols(), false);
  for (const auto& [value, i, j] : pairs) {
    if (m.index[i] >= 0 || used[j]) continue;
    m.index[i] = j;
    m.mac[i] = value;
    used[j] = true;
  }
  return m;
}

}  // namespace mmv

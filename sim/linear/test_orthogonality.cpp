#include "sim/linear/test_orthogonality.hpp"

#include <cmath>
#include <complex>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/modes/tam.hpp"

namespace mmv {

TestOrthogonality testOrthogonality(const MeasuredSet& test, const TamChannels& tam) {
  TestOrthogonality out;
  out.source = tam.source, out.method = tam.method;
  out.channels = static_cast<int>(tam.nodes.size());
  const Eigen::Index a = static_cast<Eigen::Index>(tam.nodes.size());
  MMV_DEMAND(tam.M.rows() == a && tam.M.cols() == a && tam.directions.size() == tam.nodes.size());
  std::vector<Eigen::VectorXd> columns;
  for (const auto& mode : test.modes) {
    Eigen::VectorXcd v(a);
    std::string missing;
    for (Eigen::Index c = 0; c < a; ++c) {
      const int node = tam.nodes[static_cast<std::size_t>(c)];
      std::size_t at = 0;
      while (at < mode.nodes.size() && mode.nodes[at] != node) ++at;
      if (at == mode.nodes.size()) {
        missing = strf("node %d (channel %s)", node, tam.names.empty() ? "" : tam.names[static_cast<std::size_t>(c)].c_str());
        break;
      }
      const auto& d = tam.directions[static_cast<std::size_t>(c)];
      v[c] = mode.shape[at][0] * d[0] + mode.shape[at][1] * d[1] + mode.shape[at][2] * d[2];
    }
    if (!missing.empty()) {
      out.left_out.push_back(strf("mode %d (%.4g Hz): it has no %s", mode.number, mode.frequency_hz, missing.c_str()));
      continue;
    }
    // The phase that makes the shape most nearly real (maximises sum Re^2), then its real part.
    const std::complex<double> s2 = v.array().square().sum();
    const double theta = 0.5 * std::arg(s2);
    columns.push_back((v * std::polar(1.0, -theta)).real());
    out.modes.push_back(mode.number);
    out.frequencies_hz.push_back(mode.frequency_hz);
  }
  if (columns.empty())
    throw SceneError(test.source + ": no measured mode has every channel of the TAM (" + tam.source + ": " +
                     (out.left_out.empty() ? std::string("the file has no modes") : out.left_out.front()) +
                     "): the test must measure the TAM's channels, node for node");
  const Eigen::Index t = static_cast<Eigen::Index>(columns.size());
  Eigen::MatrixXd V(a, t);
  for (Eigen::Index j = 0; j < t; ++j) V.col(j) = columns[static_cast<std::size_t>(j)];
  const Eigen::MatrixXd O = V.transpose() * tam.M * V;
  out.matrix.resize(t, t);
  out.all_pass = true;
  for (Eigen::Index i = 0; i < t; ++i) {
    double worst = 0;
    for (Eigen::Index j = 0; j < t; ++j) {
      const double d = std::sqrt(std::abs(O(i, i) * O(j, j)));
      out.matrix(i, j) = d > 0 ? O(i, j) / d : 0.0;
      if (i != j) worst = std::max(worst, std::abs(out.matrix(i, j)));
    }
    out.max_off_diagonal.push_back(worst);
    out.pass.push_back(worst <= kTamOffDiagonalMax);
    out.all_pass = out.all_pass && worst <= kTamOffDiagonalMax;
  }
  return out;
}

}  // namespace mmv

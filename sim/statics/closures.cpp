#include "sim/statics/closures.hpp"

#include <sstream>

#include "sim/scene/scene.hpp"

namespace mmv {
namespace {

SimTK::Vec3 locate(const Model& model, const SimTK::State& s, SimTK::MobilizedBodyIndex b, const SimTK::Vec3& st) {
  return model.getMatter().getMobilizedBody(b).findStationLocationInGround(s, st);
}

/// Rank of G with singular values below 1e-10 of `scale` counted as zero.
int rankOf(const Eigen::MatrixXd& G, double scale) {
  if (G.rows() == 0 || G.cols() == 0) return 0;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(G);
  int r = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()[i] > 1e-10 * scale) ++r;
  return r;
}

}  // namespace

Eigen::VectorXd calcClosureErrors(const Model& model, const SimTK::State& s) {
  Eigen::VectorXd phi(model.getNumClosureRows());
  int r = 0;
  for (const auto& c : model.getClosures()) {
    const SimTK::Vec3 pa = model.findWeightedLocation(s, c.pointsA());
    const SimTK::Vec3 pb = c.to_ground ? c.anchor_W : locate(model, s, c.mobod_b, c.station_b);
    for (const auto& e : c.directions) phi[r++] = ~e * (pa - pb);
  }
  return phi;
}

Eigen::MatrixXd calcClosureJacobian(const Model& model, const SimTK::State& s, const std::vector<int>& cols) {
  Eigen::MatrixXd G(model.getNumClosureRows(), cols.size());
  int r = 0;
  for (const auto& c : model.getClosures()) {
    const std::vector<WeightedPoint> pa = c.pointsA();
    std::vector<SimTK::MobilizedBodyIndex> b;
    std::vector<SimTK::Vec3> st;
    for (const WeightedPoint& p : pa) b.push_back(p.mobod), st.push_back(p.station_B);
    if (!c.to_ground) {
      b.push_back(c.mobod_b);
      st.push_back(c.station_b);
    }
    const Eigen::MatrixXd J = model.calcFrameJacobians(s, b, st, cols);
    Eigen::MatrixXd Jrel = Eigen::MatrixXd::Zero(3, J.cols());
    for (std::size_t i = 0; i < pa.size(); ++i) Jrel += pa[i].weight * J.middleRows(6 * static_cast<Eigen::Index>(i) + 3, 3);
    if (!c.to_ground) Jrel -= J.middleRows(6 * static_cast<Eigen::Index>(pa.size()) + 3, 3);
    for (const auto& e : c.directions) G.row(r++) = Eigen::Vector3d(e[0], e[1], e[2]).transpose() * Jrel;
  }
  return G;
}

std::vector<PointForce> closureForces(const Model& model, const Eigen::VectorXd& lambda) {
  std::vector<PointForce> out;
  int r = 0;
  for (const auto& c : model.getClosures()) {
    SimTK::Vec3 f(0);
    for (const auto& e : c.directions) f += lambda[r++] * e;
    for (const WeightedPoint& p : c.pointsA()) out.push_back({model.findBody(p.mobod), p.station_B, p.weight * f});
    if (!c.to_ground) out.push_back({model.findBody(c.mobod_b), c.station_b, -f});
  }
  return out;
}

void checkClosureRank(const Model& model, const SimTK::State& s, const std::vector<int>& dofs) {
  const auto& closures = model.getClosures();
  if (closures.empty()) return;
  const Eigen::MatrixXd G = calcClosureJacobian(model, s, dofs);
  // Lever arms set the scale of G (m/rad): the article's size.
  double scale = 0;
  for (const auto& p : model.getPoints()) scale = std::max(scale, model.findPointLocation(s, p).norm());
  scale = std::max(scale, 1e-3);
  int rows = 0, rank = 0;
  for (std::size_t i = 0; i < closures.size(); ++i) {
    const int held = static_cast<int>(closures[i].directions.size());
    const int new_rank = rankOf(G.topRows(rows + held), scale);
    if (new_rank - rank < held) {
      std::ostringstream os;
      os << closures[i].where << ": closures[" << i << "] '" << closures[i].name
         << "' over-constrains the article: of the " << held << " direction" << (held > 1 ? "s" : "")
         << " it holds, " << (new_rank - rank)
         << " can move independently of the joints and the closures before it (a closure on parts that cannot move, "
            "a duplicate, or a pin along a straight inextensible link, whose force would be indeterminate: use type: slider)";
      throw SceneError(os.str());
    }
    rows += held;
    rank = new_rank;
  }
}

Eigen::MatrixXd nullSpace(const Eigen::MatrixXd& G, int n) {
  if (G.rows() == 0) return Eigen::MatrixXd::Identity(n, n);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  const double tol = 1e-10 * (sv.size() ? sv[0] : 0.0);
  int rank = 0;
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv[i] > tol) ++rank;
  return svd.matrixV().rightCols(n - rank);
}

}  // namespace mmv

// Frame Jacobians by the tree (Model::calcFrameJacobians): each mobility's column of the
// hinge matrix H, in ground (a twist: the angular velocity and the velocity of its body's
// origin per unit u, Simbody's MobilizedBody::getHCol), moves every frame outboard of it
// as a rigid body; a frame's rows are its ancestors' twists carried to the frame's point,
//     w = H_w,    v = H_v + H_w x (p - o_B),
// and zero for every mobility off its path to ground. The cost is the frames' depths,
// not Simbody's SimbodyMatterSubsystem::calcFrameJacobian, which applies a unit force
// along each of a frame's six rows and walks the whole tree for each (6 x frames x
// bodies): at 64 segments a link that was 17 % of frf. Tests compare the two to 1e-12.
#include "sim/model/model.hpp"

#include "sim/core/errors.hpp"

namespace mmv {

Eigen::MatrixXd Model::calcFrameJacobians(const SimTK::State& s, const std::vector<SimTK::MobilizedBodyIndex>& bodies,
                                          const std::vector<SimTK::Vec3>& stations, const std::vector<int>& cols) const {
  MMV_DEMAND(bodies.size() == stations.size());
  std::vector<int> column(static_cast<std::size_t>(s.getNU()), -1);  // Simbody's u -> the column it fills
  for (std::size_t j = 0; j < cols.size(); ++j) column[uindex_[cols[j]]] = static_cast<int>(j);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(6 * static_cast<Eigen::Index>(bodies.size()), static_cast<Eigen::Index>(cols.size()));
  for (std::size_t t = 0; t < bodies.size(); ++t) {
    const SimTK::Vec3 p = matter_.getMobilizedBody(bodies[t]).findStationLocationInGround(s, stations[t]);
    for (SimTK::MobilizedBodyIndex a = bodies[t]; a != SimTK::GroundIndex;) {
      const SimTK::MobilizedBody& body = matter_.getMobilizedBody(a);
      const int first = body.getFirstUIndex(s), nu = body.getNumU(s);
      const SimTK::Vec3 arm = p - body.getBodyOriginLocation(s);
      for (int k = 0; k < nu; ++k) {
        const int j = column[static_cast<std::size_t>(first + k)];
        if (j < 0) continue;
        const SimTK::SpatialVec h = body.getHCol(s, SimTK::MobilizerUIndex(k));
        const SimTK::Vec3 v = h[1] + h[0] % arm;
        for (int r = 0; r < 3; ++r) {
          out(6 * static_cast<Eigen::Index>(t) + r, j) = h[0][r];
          out(6 * static_cast<Eigen::Index>(t) + 3 + r, j) = v[r];
        }
      }
      a = body.getParentMobilizedBody().getMobilizedBodyIndex();
    }
  }
  return out;
}

Eigen::MatrixXd Model::calcMassCentreCoupling(const SimTK::State& s, const std::vector<int>& cols) const {
  // Subtree mass and first moment about ground's origin, tips inward (a child's index is
  // above its parent's in Simbody's tree).
  const int nb = matter_.getNumBodies();
  std::vector<double> mass(static_cast<std::size_t>(nb), 0.0);
  std::vector<SimTK::Vec3> moment(static_cast<std::size_t>(nb), SimTK::Vec3(0));
  for (const BodyInfo& b : bodies_) {
    const SimTK::MobilizedBody& body = matter_.getMobilizedBody(b.mobod);
    const SimTK::MassProperties mp = body.getBodyMassProperties(s);
    mass[b.mobod] += mp.getMass();
    moment[b.mobod] += mp.getMass() * body.findStationLocationInGround(s, mp.getMassCenter());
  }
  for (int i = nb - 1; i > 0; --i) {
    const int p = matter_.getMobilizedBody(SimTK::MobilizedBodyIndex(i)).getParentMobilizedBody().getMobilizedBodyIndex();
    mass[p] += mass[i];
    moment[p] += moment[i];
  }
  std::vector<int> column(static_cast<std::size_t>(s.getNU()), -1);
  for (std::size_t j = 0; j < cols.size(); ++j) column[uindex_[cols[j]]] = static_cast<int>(j);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(cols.size()), 3);
  for (int i = 1; i < nb; ++i) {
    const SimTK::MobilizedBody& body = matter_.getMobilizedBody(SimTK::MobilizedBodyIndex(i));
    // sum m_b (H_v + H_w x (c_b - o)) = M H_v + H_w x (S - M o) over the subtree.
    const SimTK::Vec3 arm = moment[i] - mass[i] * body.getBodyOriginLocation(s);
    const int first = body.getFirstUIndex(s), nu = body.getNumU(s);
    for (int k = 0; k < nu; ++k) {
      const int j = column[static_cast<std::size_t>(first + k)];
      if (j < 0) continue;
      const SimTK::SpatialVec h = body.getHCol(s, SimTK::MobilizerUIndex(k));
      const SimTK::Vec3 f = mass[i] * h[1] + h[0] % arm;
      for (int a = 0; a < 3; ++a) out(j, a) = f[a];
    }
  }
  return out;
}

}  // namespace mmv

#include "sim/model/stations.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

struct Hermite {
  double h1, h2, h3, h4;
};

Hermite hermite(double xi) {
  const double x2 = xi * xi, x3 = x2 * xi;
  return {1 - 3 * x2 + 2 * x3, xi - 2 * x2 + x3, 3 * x2 - 2 * x3, x3 - x2};
}

}  // namespace

StationPoint::StationPoint(const Model& model, const StationSpec& spec) : model_(&model), spec_(spec) {
  const LinkAxis* axis = model.findLinkAxis(spec.link);
  MMV_DEMAND(axis != nullptr && axis->x.size() >= 2);
  std::size_t k = 0;
  while (k + 2 < axis->x.size() && spec.x > axis->x[k + 1]) ++k;
  auto node = [&](std::size_t i) {
    const NamedPoint& p = model.getPoints()[axis->points[i]];
    return Node{p.mobod, axis->left[i], axis->right[i], p.station_B};
  };
  a_ = node(k);
  b_ = node(k + 1);
  ell_ = axis->x[k + 1] - axis->x[k];
  xi_ = std::clamp((spec.x - axis->x[k]) / ell_, 0.0, 1.0);
}

SimTK::Vec3 StationPoint::interpolate(const NodeVector& point, const BodyVector& axis) const {
  // A node's body axis k: the mean of its two pieces', interpolated linearly.
  auto along = [&](int k) {
    auto node = [&](const Node& n) { return 0.5 * (axis(n.left, k) + axis(n.right, k)); };
    return std::pair<SimTK::Vec3, SimTK::Vec3>(node(a_), node(b_));
  };
  const Hermite h = hermite(xi_);
  const auto [ea, eb] = along(0);
  SimTK::Vec3 p = h.h1 * point(a_) + h.h2 * ell_ * ea + h.h3 * point(b_) + h.h4 * ell_ * eb;
  if (spec_.offset != 0) {
    const auto [ya, yb] = along(1);
    p += spec_.offset * ((1 - xi_) * ya + xi_ * yb);
  }
  if (spec_.offset_z != 0) {
    const auto [za, zb] = along(2);
    p += spec_.offset_z * ((1 - xi_) * za + xi_ * zb);
  }
  return p;
}

std::vector<WeightedPoint> StationPoint::weightedPoints() const {
  const Hermite h = hermite(xi_);
  std::vector<WeightedPoint> out{{a_.point_body, a_.station_B, h.h1}, {b_.point_body, b_.station_B, h.h3}};
  // c times a node's body axis k, the mean of its two pieces': c/2 (p(e_k) - p(0)) on each.
  auto axis = [&](const Node& n, int k, double c) {
    for (const SimTK::MobilizedBodyIndex piece : {n.left, n.right}) {
      SimTK::Vec3 e(0);
      e[k] = 1;
      out.push_back({piece, e, 0.5 * c});
      out.push_back({piece, SimTK::Vec3(0), -0.5 * c});
    }
  };
  axis(a_, 0, h.h2 * ell_);
  axis(b_, 0, h.h4 * ell_);
  for (const auto& [k, offset] : {std::pair{1, spec_.offset}, std::pair{2, spec_.offset_z}})
    if (offset != 0) {
      axis(a_, k, offset * (1 - xi_));
      axis(b_, k, offset * xi_);
    }
  return out;
}

SimTK::Vec3 StationPoint::position(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  return interpolate(
      [&](const Node& n) { return m.getMobilizedBody(n.point_body).findStationLocationInGround(s, n.station_B); },
      [&](SimTK::MobilizedBodyIndex b, int k) { return SimTK::Vec3(m.getMobilizedBody(b).getBodyRotation(s)(k)); });
}

SimTK::Vec3 StationPoint::velocity(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  return interpolate(
      [&](const Node& n) { return m.getMobilizedBody(n.point_body).findStationVelocityInGround(s, n.station_B); },
      [&](SimTK::MobilizedBodyIndex b, int k) {  // e' = w x e
        const auto& mb = m.getMobilizedBody(b);
        return SimTK::Vec3(mb.getBodyAngularVelocity(s) % mb.getBodyRotation(s)(k));
      });
}

SimTK::Vec3 StationPoint::acceleration(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  return interpolate(
      [&](const Node& n) { return m.getMobilizedBody(n.point_body).findStationAccelerationInGround(s, n.station_B); },
      [&](SimTK::MobilizedBodyIndex b, int k) {  // e'' = alpha x e + w x (w x e)
        const auto& mb = m.getMobilizedBody(b);
        const SimTK::Vec3 e = mb.getBodyRotation(s)(k), w = mb.getBodyAngularVelocity(s);
        return SimTK::Vec3(mb.getBodyAngularAcceleration(s) % e + w % (w % e));
      });
}

SimTK::Vec3 StationPoint::direction(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  auto dir = [&](const Node& n) {
    return 0.5 * (m.getMobilizedBody(n.left).getBodyRotation(s).x() + m.getMobilizedBody(n.right).getBodyRotation(s).x());
  };
  return ((1 - xi_) * dir(a_) + xi_ * dir(b_)).normalize();
}

double StationPoint::angularRate(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  auto w = [&](const Node& n) {
    return 0.5 * (m.getMobilizedBody(n.left).getBodyAngularVelocity(s)[2] + m.getMobilizedBody(n.right).getBodyAngularVelocity(s)[2]);
  };
  return (1 - xi_) * w(a_) + xi_ * w(b_);
}

SimTK::Vec3 StationPoint::angularVelocity(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  auto w = [&](const Node& n) {
    return 0.5 * (m.getMobilizedBody(n.left).getBodyAngularVelocity(s) + m.getMobilizedBody(n.right).getBodyAngularVelocity(s));
  };
  return (1 - xi_) * w(a_) + xi_ * w(b_);
}

SimTK::Vec3 StationPoint::normal(const SimTK::State& s) const {
  const auto& m = model_->getMatter();
  auto z = [&](const Node& n) {
    return 0.5 * (m.getMobilizedBody(n.left).getBodyRotation(s).z() + m.getMobilizedBody(n.right).getBodyRotation(s).z());
  };
  return ((1 - xi_) * z(a_) + xi_ * z(b_)).normalize();
}

Eigen::MatrixXd StationPoint::translationJacobian(const SimTK::State& s, const std::vector<int>& dofs, int rows) const {
  const auto& m = model_->getMatter();
  // Frames: the two node points, then the pieces whose directions enter.
  const std::vector<SimTK::MobilizedBodyIndex> bodies{a_.point_body, b_.point_body, a_.left, a_.right, b_.left, b_.right};
  const std::vector<SimTK::Vec3> stations{a_.station_B, b_.station_B, SimTK::Vec3(0), SimTK::Vec3(0), SimTK::Vec3(0),
                                          SimTK::Vec3(0)};
  const Eigen::MatrixXd J = model_->calcFrameJacobians(s, bodies, stations, dofs);  // (w; v) per frame
  auto axis = [&](SimTK::MobilizedBodyIndex b, int k) {
    const SimTK::Vec3 e = m.getMobilizedBody(b).getBodyRotation(s)(k);
    return Eigen::Vector3d(e[0], e[1], e[2]);
  };
  // d e / d q_c = (J_w,c x e) for each piece's body axis k; a node's is the mean of two.
  auto dirRows = [&](int left_frame, int right_frame, SimTK::MobilizedBodyIndex left, SimTK::MobilizedBodyIndex right,
                     int k) {
    Eigen::MatrixXd D(3, dofs.size());
    const Eigen::Vector3d el = axis(left, k), er = axis(right, k);
    for (Eigen::Index c = 0; c < D.cols(); ++c) {
      const Eigen::Vector3d wl = J.block<3, 1>(6 * left_frame, c), wr = J.block<3, 1>(6 * right_frame, c);
      D.col(c) = 0.5 * (wl.cross(el) + wr.cross(er));
    }
    return D;
  };
  auto interpolated = [&](int k) {
    return Eigen::MatrixXd((1 - xi_) * dirRows(2, 3, a_.left, a_.right, k) + xi_ * dirRows(4, 5, b_.left, b_.right, k));
  };
  const Eigen::MatrixXd Da = dirRows(2, 3, a_.left, a_.right, 0), Db = dirRows(4, 5, b_.left, b_.right, 0);
  const Hermite h = hermite(xi_);
  Eigen::MatrixXd P = h.h1 * J.middleRows(3, 3) + h.h2 * ell_ * Da + h.h3 * J.middleRows(9, 3) + h.h4 * ell_ * Db;
  if (spec_.offset != 0) P += spec_.offset * interpolated(1);
  if (spec_.offset_z != 0) P += spec_.offset_z * interpolated(2);
  return P.topRows(rows);
}

Eigen::MatrixXd StationPoint::rotationJacobian(const SimTK::State& s, const std::vector<int>& dofs) const {
  const Eigen::MatrixXd J = model_->calcFrameJacobians(s, {a_.left, a_.right, b_.left, b_.right},
                                                       std::vector<SimTK::Vec3>(4, SimTK::Vec3(0)), dofs);
  return 0.5 * (1 - xi_) * (J.middleRows(0, 3) + J.middleRows(6, 3)) + 0.5 * xi_ * (J.middleRows(12, 3) + J.middleRows(18, 3));
}

std::optional<PointRef> PointRef::resolve(const Model& model, const ArticleSpec& article, const std::string& name,
                                          std::string& error) {
  PointRef r(model, name);
  if (isStationName(name)) {
    const std::optional<StationSpec> spec = parseStation(name, article, error);
    if (!spec) return std::nullopt;
    r.station_.emplace(model, *spec);
    return r;
  }
  r.point_ = model.findPoint(name);
  if (!r.point_) {
    error = "unknown point '" + name +
            "' (points are <joint>, <link>.root, <link>.tip and <link>.h1 .. <link>.h<segments>; stations "
            "<link>@<m>m or <link>@<fraction>)";
    return std::nullopt;
  }
  return r;
}

SimTK::Vec3 PointRef::position(const SimTK::State& s) const {
  if (station_) return station_->position(s);
  return model_->getMatter().getMobilizedBody(point_->mobod).findStationLocationInGround(s, point_->station_B);
}

SimTK::Vec3 PointRef::velocity(const SimTK::State& s) const {
  if (station_) return station_->velocity(s);
  return model_->getMatter().getMobilizedBody(point_->mobod).findStationVelocityInGround(s, point_->station_B);
}

SimTK::Vec3 PointRef::acceleration(const SimTK::State& s) const {
  if (station_) return station_->acceleration(s);
  return model_->getMatter().getMobilizedBody(point_->mobod).findStationAccelerationInGround(s, point_->station_B);
}

double PointRef::angularRate(const SimTK::State& s) const {
  if (station_) return station_->angularRate(s);
  return model_->getMatter().getMobilizedBody(point_->mobod).getBodyAngularVelocity(s)[2];
}

double PointRef::angularRate(const SimTK::State& s, int axis) const {
  if (axis == 2 && !model_->isSpatial()) return angularRate(s);
  const SimTK::Vec3 w = station_ ? station_->angularVelocity(s)
                                 : model_->getMatter().getMobilizedBody(point_->mobod).getBodyAngularVelocity(s);
  return ~w * localAxis(s, axis);
}

SimTK::Vec3 PointRef::localAxis(const SimTK::State& s, int axis) const {
  const SimTK::Rotation* R =
      station_ ? nullptr : &model_->getMatter().getMobilizedBody(point_->mobod).getBodyRotation(s);
  const SimTK::Vec3 x = station_ ? station_->direction(s) : SimTK::Vec3(R->x());
  if (!model_->isSpatial()) {  // the plane's normal is z: y = z x x
    if (axis == 2) return SimTK::Vec3(0, 0, 1);
    return axis == 0 ? x : SimTK::Vec3(-x[1], x[0], 0);
  }
  // The section's normal, made orthogonal to the (interpolated) link direction.
  const SimTK::Vec3 n = station_ ? station_->normal(s) : SimTK::Vec3(R->z());
  const SimTK::Vec3 y = (n % x).normalize();
  return axis == 0 ? x : axis == 1 ? y : SimTK::Vec3(x % y);
}

Eigen::MatrixXd PointRef::translationJacobian(const SimTK::State& s, const std::vector<int>& dofs, int rows) const {
  if (station_) return station_->translationJacobian(s, dofs, rows);
  const Eigen::MatrixXd J = model_->calcFrameJacobians(s, {point_->mobod}, {point_->station_B}, dofs);
  return J.middleRows(3, rows);
}

Eigen::MatrixXd PointRef::rotationJacobian(const SimTK::State& s, const std::vector<int>& dofs) const {
  if (station_) return station_->rotationJacobian(s, dofs);
  return model_->calcFrameJacobians(s, {point_->mobod}, {point_->station_B}, dofs).topRows(3);
}

Eigen::RowVectorXd strainRow(const PointRef& a, const PointRef& b, const SimTK::State& s, const std::vector<int>& dofs,
                             double c_over_span, bool out_of_plane) {
  const int k = out_of_plane ? 1 : 2;
  auto turn = [&](const PointRef& p) {
    const SimTK::Vec3 n = p.localAxis(s, k);
    return Eigen::RowVectorXd(Eigen::RowVector3d(n[0], n[1], n[2]) * p.rotationJacobian(s, dofs));
  };
  return (out_of_plane ? c_over_span : -c_over_span) * (turn(b) - turn(a));
}

double strainReading(const PointRef& a, const PointRef& b, const SimTK::State& s, double c_over_span, bool out_of_plane) {
  const SimTK::Vec3 xb = b.localAxis(s, 0);
  const double along = ~xb * a.localAxis(s, 0);
  if (out_of_plane) return c_over_span * std::atan2(-(~xb * a.localAxis(s, 2)), along);
  return -c_over_span * std::atan2(~xb * a.localAxis(s, 1), along);
}

}  // namespace mmv

#include "sim/hamsas/spatial_linear.hpp"

#include <cmath>

#include "sim/core/linalg.hpp"
#include "sim/core/errors.hpp"

namespace mmv {
namespace {

using cd = std::complex<double>;

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

/// Second-order term of g . p for a point at offset c turned by theta: the Hessian of
/// g . (1/2 theta x (theta x c)).
Eigen::Matrix3d preloadHessian(const Eigen::Vector3d& g, const Eigen::Vector3d& c) {
  return 0.5 * (g * c.transpose() + c * g.transpose()) - g.dot(c) * Eigen::Matrix3d::Identity();
}

Eigen::Vector3d originOf(const SpatialSpec& s, int body) { return body == 0 ? s.reference : s.bodies[body].com; }

/// Selects body i's rotation coordinates (3 x 6N).
Eigen::MatrixXd rotationRows(int nb, int body) {
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(3, 6 * nb);
  E.block<3, 3>(0, 6 * body + 3).setIdentity();
  return E;
}

struct Assembly {
  Eigen::MatrixXd K_el, C;  // full (6 nb), elastic only
  std::vector<Eigen::MatrixXd> element_el;  // full, elastic, per element (springs then angular)
  std::vector<Eigen::MatrixXd> D;           // per point spring: 3 x 6nb relative displacement
  std::vector<Eigen::MatrixXd> R;           // per angular spring: 3 x 6nb relative rotation
};

}  // namespace

Eigen::MatrixXd spatialPointJacobian(const SpatialSpec& s, int body, const Eigen::Vector3d& p) {
  const int nb = static_cast<int>(s.bodies.size());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3, 6 * nb);
  J.block<3, 3>(0, 6 * body).setIdentity();
  J.block<3, 3>(0, 6 * body + 3) = -skew(p - originOf(s, body));
  return J;
}

namespace {

/// Elastic stiffness and damping of every element, and their kinematic maps.
/// `joint_rows` receives the point springs held as ideal constraints.
Assembly assemble(const SpatialSpec& s, bool ideal_joints, std::vector<int>& joint_rows) {
  const int nb = static_cast<int>(s.bodies.size()), N = 6 * nb;
  Assembly a;
  a.K_el = Eigen::MatrixXd::Zero(N, N);
  a.C = Eigen::MatrixXd::Zero(N, N);
  for (std::size_t e = 0; e < s.springs.size(); ++e) {
    const PointSpring& sp = s.springs[e];
    const Eigen::MatrixXd D = spatialPointJacobian(s, sp.b, sp.point) - spatialPointJacobian(s, sp.a, sp.point);
    a.D.push_back(D);
    const bool constraint = ideal_joints && sp.joint;
    Eigen::MatrixXd Ke = constraint ? Eigen::MatrixXd::Zero(N, N)
                                    : Eigen::MatrixXd(D.transpose() * sp.stiffness.asDiagonal() * D);
    a.element_el.push_back(Ke);
    a.K_el += Ke;
    if (!constraint) a.C += D.transpose() * sp.damping.asDiagonal() * D;
    if (constraint) joint_rows.push_back(static_cast<int>(e));
  }
  for (const AngularSpring& as : s.angular) {
    const Eigen::MatrixXd R = rotationRows(nb, as.b) - rotationRows(nb, as.a);
    a.R.push_back(R);
    Eigen::MatrixXd Ke = R.transpose() * as.stiffness.asDiagonal() * R;
    a.element_el.push_back(Ke);
    a.K_el += Ke;
    a.C += R.transpose() * as.damping.asDiagonal() * R;
  }
  return a;
}

/// Preloads: the linear-elastic force distribution that balances gravity `f` at the
/// design. Pendulums are mechanisms of the elastic stiffness alone (their stiffness is
/// the preload's), so the system is solved in the least-squares sense over the elastic
/// range; the null-space part moves no element, so the element forces are unique. The
/// equilibrium residual (checked by the caller) says whether gravity is really carried.
/// Returns the displacements u (free bodies) and the ideal joints' forces lambda.
void solvePreload(const Eigen::MatrixXd& Kff_el, const Eigen::MatrixXd& G, const Eigen::VectorXd& f, Eigen::VectorXd& u,
                  Eigen::VectorXd& lambda) {
  const int n = static_cast<int>(Kff_el.rows()), m = static_cast<int>(G.rows());
  // Constraint rows scaled to the stiffness so the bordered matrix keeps its conditioning.
  const double alpha = std::max(Kff_el.diagonal().cwiseAbs().maxCoeff(), 1.0);
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + m, n + m);
  kkt.topLeftCorner(n, n) = Kff_el;
  if (m > 0) {
    kkt.topRightCorner(n, m) = alpha * G.transpose();
    kkt.bottomLeftCorner(m, n) = alpha * G;
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
  rhs.head(n) = f;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(kkt);
  if (es.info() != Eigen::Success) throw NumericalError("spatial model: the static preload solution failed");
  const Eigen::VectorXd ev = es.eigenvalues();
  const double cut = 1e-12 * ev.cwiseAbs().maxCoeff();
  Eigen::VectorXd coeff = es.eigenvectors().transpose() * rhs;
  for (int i = 0; i < ev.size(); ++i) coeff[i] = std::abs(ev[i]) > cut ? coeff[i] / ev[i] : 0.0;
  const Eigen::VectorXd sol = es.eigenvectors() * coeff;
  u = sol.head(n);
  lambda = alpha * sol.tail(m);
}

/// Element forces at the preload and the geometric stiffness each adds (into
/// `element`, per element, full size); returns the total stiffness.
Eigen::MatrixXd addPreloadStiffness(const SpatialSpec& s, bool ideal_joints, const Assembly& a, const Eigen::VectorXd& ufull,
                                    const Eigen::VectorXd& lambda, SpatialLinearization& lin,
                                    std::vector<Eigen::MatrixXd>& element) {
  const int N = static_cast<int>(ufull.size());
  Eigen::MatrixXd K = a.K_el;
  element.assign(a.element_el.size(), Eigen::MatrixXd::Zero(N, N));
  int joint_k = 0;
  for (std::size_t e = 0; e < s.springs.size(); ++e) {
    const PointSpring& sp = s.springs[e];
    const bool constraint = ideal_joints && sp.joint;
    // g: the gradient of the element's energy with respect to d = p_b - p_a.
    const Eigen::Vector3d g = constraint ? Eigen::Vector3d(lambda.segment<3>(3 * joint_k++))
                                         : Eigen::Vector3d(sp.stiffness.cwiseProduct(a.D[e] * ufull));
    lin.spring_force.push_back(g);  // force on a is +g, on b is -g
    Eigen::MatrixXd Kg = Eigen::MatrixXd::Zero(N, N);
    Kg.block<3, 3>(6 * sp.b + 3, 6 * sp.b + 3) += preloadHessian(g, sp.point - originOf(s, sp.b));
    Kg.block<3, 3>(6 * sp.a + 3, 6 * sp.a + 3) -= preloadHessian(g, sp.point - originOf(s, sp.a));
    element[e] += Kg;
    K += Kg;
  }
  for (std::size_t e = 0; e < s.angular.size(); ++e) {
    const AngularSpring& as = s.angular[e];
    const Eigen::Vector3d m0 = as.stiffness.cwiseProduct(a.R[e] * ufull);
    lin.angular_moment.push_back(m0);
    Eigen::MatrixXd Kg = Eigen::MatrixXd::Zero(N, N);
    Kg.block<3, 3>(6 * as.a + 3, 6 * as.b + 3) += -0.5 * skew(m0);
    Kg.block<3, 3>(6 * as.b + 3, 6 * as.a + 3) += 0.5 * skew(m0);
    element[s.springs.size() + e] += Kg;
    K += Kg;
  }
  return K;
}

/// Mass, stiffness, damping over the free bodies, each element's share, and the
/// constrained (Z) forms; `G` holds the ideal joints' rows.
void finishMatrices(const SpatialSpec& s, const Assembly& a, const Eigen::MatrixXd& K,
                    const std::vector<Eigen::MatrixXd>& element, const Eigen::MatrixXd& G, bool has_joints,
                    SpatialLinearization& lin) {
  const int nb = static_cast<int>(s.bodies.size()), n = 6 * nb - 6;
  lin.M = Eigen::MatrixXd::Zero(n, n);
  for (int b = 1; b < nb; ++b) {
    lin.M.block<3, 3>(6 * (b - 1), 6 * (b - 1)) = s.bodies[b].mass * Eigen::Matrix3d::Identity();
    lin.M.block<3, 3>(6 * (b - 1) + 3, 6 * (b - 1) + 3) = s.bodies[b].inertia;
  }
  lin.K = K.bottomRightCorner(n, n);
  symmetrize(lin.K);
  lin.C = a.C.bottomRightCorner(n, n);
  lin.Kb = K.bottomLeftCorner(n, 6);
  lin.Cb = a.C.bottomLeftCorner(n, 6);
  for (std::size_t e = 0; e < element.size(); ++e) {
    const bool is_spring = e < s.springs.size();
    const std::string& name = is_spring ? s.springs[e].name : s.angular[e - s.springs.size()].name;
    const std::string& group = is_spring ? s.springs[e].group : s.angular[e - s.springs.size()].group;
    lin.elements.push_back({name, group, a.element_el[e].bottomRightCorner(n, n), element[e].bottomRightCorner(n, n)});
  }
  if (!has_joints) {
    lin.Z = Eigen::MatrixXd::Identity(n, n);
  } else {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(G, Eigen::ComputeFullV);
    const Eigen::VectorXd sv = svd.singularValues();
    int rank = 0;
    for (int i = 0; i < sv.size(); ++i) rank += sv[i] > 1e-10 * sv[0];
    lin.redundant_constraints = static_cast<int>(G.rows()) - rank;
    lin.Z = svd.matrixV().rightCols(n - rank);
  }
  lin.Mz = lin.Z.transpose() * lin.M * lin.Z;
  lin.Kz = lin.Z.transpose() * lin.K * lin.Z;
  lin.Cz = lin.Z.transpose() * lin.C * lin.Z;
  symmetrize(lin.Mz);
  symmetrize(lin.Kz);
}

}  // namespace

SpatialLinearization linearizeSpatial(const SpatialSpec& s, bool ideal_joints) {
  const int nb = static_cast<int>(s.bodies.size());
  MMV_DEMAND(nb >= 2);  // the base and at least one body
  const int N = 6 * nb, n = N - 6;
  SpatialLinearization lin;
  lin.ideal_joints = ideal_joints;
  lin.num_free = n;
  std::vector<int> joint_rows;  // indices of constraint springs (ideal)
  const Assembly a = assemble(s, ideal_joints, joint_rows);
  // Gravity on the free bodies' mass centres.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  double weight = 0;
  for (int b = 1; b < nb; ++b) {
    f.segment<3>(6 * (b - 1)) = s.bodies[b].mass * s.gravity;
    weight += s.bodies[b].mass * s.gravity.norm();
  }
  Eigen::MatrixXd G(3 * joint_rows.size(), n);
  for (std::size_t j = 0; j < joint_rows.size(); ++j) G.middleRows(3 * j, 3) = a.D[joint_rows[j]].rightCols(n);
  Eigen::VectorXd u, lambda;
  solvePreload(a.K_el.bottomRightCorner(n, n), G, f, u, lambda);
  Eigen::VectorXd ufull = Eigen::VectorXd::Zero(N);
  ufull.tail(n) = u;
  std::vector<Eigen::MatrixXd> element;
  const Eigen::MatrixXd K = addPreloadStiffness(s, ideal_joints, a, ufull, lambda, lin, element);
  // Equilibrium check at the design: gravity against every element's force.
  Eigen::VectorXd res = f;
  for (std::size_t e = 0; e < s.springs.size(); ++e) res -= a.D[e].rightCols(n).transpose() * lin.spring_force[e];
  for (std::size_t e = 0; e < s.angular.size(); ++e) res -= a.R[e].rightCols(n).transpose() * lin.angular_moment[e];
  lin.equilibrium_residual = weight > 0 ? res.norm() / weight : res.norm();
  if (!(lin.equilibrium_residual < 1e-8))
    throw NumericalError("spatial model: the elements cannot carry gravity at the design configuration (equilibrium residual " +
                         std::to_string(lin.equilibrium_residual) + " of the weight): a loaded mechanism");
  finishMatrices(s, a, K, element, G, !joint_rows.empty(), lin);
  return lin;
}

ModalSolution spatialModes(const SpatialLinearization& lin) {
  ModalSolution m = solveModes(lin.Mz, lin.Kz);
  m.shapes = lin.Z * m.shapes;
  return m;
}

Eigen::MatrixXcd spatialTransmissibility(const SpatialSpec& s, const SpatialLinearization& lin, double w) {
  const Eigen::MatrixXcd dyn = lin.Kz.cast<cd>() - w * w * lin.Mz.cast<cd>() + cd(0, w) * lin.Cz.cast<cd>();
  const Eigen::MatrixXcd rhs = -(lin.Z.transpose() * lin.Kb).cast<cd>() - cd(0, w) * (lin.Z.transpose() * lin.Cb).cast<cd>();
  const Eigen::MatrixXcd q = lin.Z.cast<cd>() * dyn.partialPivLu().solve(rhs);
  return q.middleRows(SpatialLinearization::row(s.output_body), 6);
}

Eigen::MatrixXd spatialSensorMatrix(const SpatialSpec& s) {
  const int n = 6 * (static_cast<int>(s.bodies.size()) - 1);
  Eigen::MatrixXd C(s.sensors.size(), n);
  for (std::size_t i = 0; i < s.sensors.size(); ++i) {
    const RelativeSensor& r = s.sensors[i];
    const Eigen::MatrixXd D = spatialPointJacobian(s, r.b, r.point) - spatialPointJacobian(s, r.a, r.point);
    C.row(i) = r.direction.transpose() * D.rightCols(n);
  }
  return C;
}

}  // namespace mmv

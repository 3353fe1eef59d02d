#include "sim/linear/state_space.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"

namespace mmv {

using cd = std::complex<double>;

Eigen::MatrixXcd StateSpace::response(double omega) const {
  const Eigen::MatrixXcd sEA = cd(0, omega) * E.cast<cd>() - A.cast<cd>();
  const Eigen::MatrixXcd X = sEA.partialPivLu().solve(B.cast<cd>());
  return C.cast<cd>() * X + D.cast<cd>();
}

StateSpace StateSpace::standardForm() const {
  StateSpace s = *this;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(E);
  s.A = lu.solve(A);
  s.B = lu.solve(B);
  s.E = Eigen::MatrixXd::Identity(A.rows(), A.cols());
  return s;
}

Eigen::VectorXcd StateSpace::poles() const {
  Eigen::EigenSolver<Eigen::MatrixXd> es(E.partialPivLu().solve(A), false);
  return es.eigenvalues();
}

std::vector<double> logFrequencies(double f0, double f1, int n) {
  std::vector<double> f(n);
  for (int i = 0; i < n; ++i) f[i] = f0 * std::pow(f1 / f0, n > 1 ? double(i) / (n - 1) : 0.0);
  return f;
}

std::vector<InputSpec> defaultInputs() {
  return {{"table_x", InputKind::BaseAcceleration, "", 0}, {"table_y", InputKind::BaseAcceleration, "", 1}};
}

std::vector<OutputSpec> defaultOutputs(const ArticleScene& scene) {
  std::vector<OutputSpec> out;
  for (const auto& l : scene.article.links)
    for (int a = 0; a < 2; ++a)
      out.push_back({l.name + ".tip_a" + (a ? "y" : "x"), OutputKind::Acceleration, l.name + ".tip", a, true});
  return out;
}

StateSpace secondOrderModel(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& K,
                            const Eigen::MatrixXd& Bq, const Eigen::MatrixXd& Cd, const Eigen::MatrixXd& Cv,
                            const Eigen::MatrixXd& Ca, const Eigen::MatrixXd& Dextra) {
  const Eigen::Index n = M.rows(), ni = Bq.cols();
  const Eigen::Index no = std::max({Cd.rows(), Cv.rows(), Ca.rows(), Dextra.rows()});
  auto rows = [&](const Eigen::MatrixXd& X) { return X.size() ? X : Eigen::MatrixXd::Zero(no, n); };
  StateSpace ss;
  ss.E = Eigen::MatrixXd::Identity(2 * n, 2 * n);
  ss.E.bottomRightCorner(n, n) = M;
  ss.A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  ss.A.topRightCorner(n, n) = Eigen::MatrixXd::Identity(n, n);
  ss.A.bottomLeftCorner(n, n) = -K;
  ss.A.bottomRightCorner(n, n) = -C;
  ss.B = Eigen::MatrixXd::Zero(2 * n, ni);
  ss.B.bottomRows(n) = Bq;
  // q'' = M^-1 (Bq u - C q' - K q): an acceleration row P becomes P M^-1 [-K -C], D = P M^-1 Bq.
  const Eigen::MatrixXd PMi = M.partialPivLu().solve(rows(Ca).transpose()).transpose();  // (M symmetric)
  ss.C.resize(no, 2 * n);
  ss.C << rows(Cd) - PMi * K, rows(Cv) - PMi * C;
  ss.D = PMi * Bq + (Dextra.size() ? Dextra : Eigen::MatrixXd::Zero(no, ni));
  return ss;
}

Eigen::MatrixXcd SecondOrderResponse::response(double w) const {
  const Eigen::MatrixXcd dyn = K.cast<cd>() - w * w * M.cast<cd>() + cd(0, w) * C.cast<cd>();
  const Eigen::MatrixXcd q = dyn.partialPivLu().solve(Bq.cast<cd>());  // per unit input
  return Cd.cast<cd>() * q + cd(0, w) * Cv.cast<cd>() * q - w * w * Ca.cast<cd>() * q + D.cast<cd>();
}

LinearModel buildLinearModel(const ArticleScene& scene, const std::vector<InputSpec>& inputs,
                             const std::vector<OutputSpec>& outputs, const DampingSpec& damping) {
  LinearModel lm;
  lm.solved = solveScene(scene);
  lm.inputs = inputs;
  lm.outputs = outputs;
  const Model& model = *lm.solved.model;
  const LinearizedModel& lin = lm.solved.linearized;
  const std::vector<int>& dofs = lin.dofs;
  const int n = static_cast<int>(dofs.size());
  lm.Z = lin.Z;
  const Eigen::MatrixXd& Z = lm.Z;
  const int nz = static_cast<int>(Z.cols());
  lm.Mz = Z.transpose() * lin.M * Z;
  lm.Kz = Z.transpose() * lin.K * Z;
  lm.Mz = 0.5 * (lm.Mz + lm.Mz.transpose());
  lm.Kz = 0.5 * (lm.Kz + lm.Kz.transpose());
  if (damping.kind == DampingSpec::Kind::Rayleigh) {
    lm.Cz = damping.alpha * lm.Mz + damping.beta * lm.Kz;
  } else if (damping.kind == DampingSpec::Kind::HingeViscous) {
    Eigen::VectorXd c(n);
    for (int a = 0; a < n; ++a) {
      const Coordinate& co = model.getCoordinates()[dofs[a]];
      c[a] = co.kind == CoordinateKind::Hinge ? damping.hinge_beta * co.stiffness : 0.0;
    }
    lm.Cz = Z.transpose() * c.asDiagonal() * Z;
  } else {
    const ModalSolution modes = solveModes(lm.Mz, lm.Kz);
    Eigen::VectorXd c(nz);
    for (int i = 0; i < nz; ++i) c[i] = 2 * damping.modal_ratio * std::sqrt(std::max(modes.omega2[i], 0.0));
    lm.Cz = lm.Mz * modes.shapes * c.asDiagonal() * modes.shapes.transpose() * lm.Mz;
  }

  SimTK::State st = lm.solved.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  // Base coupling M_qb e_a = sum_b m_b J_b^T e_a (mass centres), over the DOFs.
  Eigen::MatrixXd Mqb = Eigen::MatrixXd::Zero(n, 2);
  {
    std::vector<SimTK::MobilizedBodyIndex> ix;
    std::vector<SimTK::Vec3> com;
    std::vector<double> mass;
    for (const auto& b : model.getBodies()) {
      const auto mp = model.getMatter().getMobilizedBody(b.mobod).getBodyMassProperties(st);
      ix.push_back(b.mobod);
      com.push_back(mp.getMassCenter());
      mass.push_back(mp.getMass());
    }
    const Eigen::MatrixXd J = model.calcFrameJacobians(st, ix, com, dofs);
    for (std::size_t b = 0; b < ix.size(); ++b)
      for (int a = 0; a < 2; ++a) Mqb.col(a) += mass[b] * J.row(6 * b + 3 + a).transpose();
  }
  auto pointRow = [&](const std::string& point, int axis, const std::string& what) {
    const NamedPoint* p = model.findPoint(point);
    if (!p) throw SceneError(scene.source + ": " + what + ": unknown point '" + point + "'");
    const Eigen::MatrixXd J = model.calcFrameJacobians(st, {p->mobod}, {p->station_B}, dofs);
    return Eigen::RowVectorXd(J.row(3 + axis));
  };

  const int ni = static_cast<int>(inputs.size()), no = static_cast<int>(outputs.size());
  lm.Bq = Eigen::MatrixXd::Zero(nz, ni);
  for (int k = 0; k < ni; ++k) {
    const InputSpec& in = inputs[k];
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);  // generalized force per unit input
    switch (in.kind) {
      case InputKind::BaseAcceleration: g = -Mqb.col(in.axis); break;
      case InputKind::PointForce: g = pointRow(in.target, in.axis, "input " + in.name).transpose(); break;
      case InputKind::JointTorque: {
        int row = -1;
        for (int a = 0; a < n; ++a)
          if (model.getCoordinates()[dofs[a]].name == in.target) row = a;
        if (row < 0) {
          bool exists = false;
          for (const auto& c : model.getCoordinates()) exists = exists || c.name == in.target;
          throw SceneError(scene.source + ": input " + in.name + ": " +
                           (exists ? "joint '" + in.target + "' is locked (hold: locked), so a torque there moves nothing; use hold: free or servo"
                                   : "unknown joint '" + in.target + "'"));
        }
        g[row] = 1.0;
        break;
      }
    }
    lm.Bq.col(k) = Z.transpose() * g;
  }

  const int nzo = nz;
  Eigen::MatrixXd Cd = Eigen::MatrixXd::Zero(no, nzo), Cv = Eigen::MatrixXd::Zero(no, nzo), Ca = Eigen::MatrixXd::Zero(no, nzo);
  Eigen::MatrixXd Dx = Eigen::MatrixXd::Zero(no, ni);
  bool base_input = false;
  for (const auto& in : inputs) base_input = base_input || in.kind == InputKind::BaseAcceleration;
  for (int r = 0; r < no; ++r) {
    const OutputSpec& out = outputs[r];
    const Eigen::RowVectorXd P = pointRow(out.point, out.axis, "output " + out.name) * Z;
    if (out.absolute && out.kind != OutputKind::Acceleration && base_input)
      throw SceneError(scene.source + ": output " + out.name +
                       ": an absolute displacement or velocity needs the base's displacement, not its acceleration: use an "
                       "absolute acceleration (transmissibility) or a relative output");
    if (out.kind == OutputKind::Displacement) Cd.row(r) = P;
    if (out.kind == OutputKind::Velocity) Cv.row(r) = P;
    if (out.kind == OutputKind::Acceleration) {
      Ca.row(r) = P;
      if (out.absolute)  // the base's own acceleration
        for (int k = 0; k < ni; ++k)
          if (inputs[k].kind == InputKind::BaseAcceleration && inputs[k].axis == out.axis) Dx(r, k) = 1.0;
    }
  }
  lm.full = secondOrderModel(lm.Mz, lm.Cz, lm.Kz, lm.Bq, Cd, Cv, Ca, Dx);
  lm.second_order = {lm.Mz, lm.Cz, lm.Kz, lm.Bq, Cd, Cv, Ca, Dx};
  StateSpace& ss = lm.full;
  const char* in_units[] = {"m/s^2", "N*m", "N"};
  for (const auto& in : inputs) {
    ss.input_names.push_back(in.name);
    ss.input_units.push_back(in_units[static_cast<int>(in.kind)]);
  }
  const char* out_units[] = {"m", "m/s", "m/s^2"};
  for (const auto& out : outputs) {
    ss.output_names.push_back(out.name);
    ss.output_units.push_back(out_units[static_cast<int>(out.kind)]);
  }
  const bool open = lin.G.rows() == 0;
  for (int i = 0; i < nz; ++i)
    ss.state_names.push_back(open ? model.getCoordinates()[dofs[i]].name : "eta" + std::to_string(i + 1));
  for (int i = 0; i < nz; ++i) ss.state_names.push_back(ss.state_names[i] + "_dot");
  return lm;
}

ReducedModel reduceModal(const StateSpace& full, const ReductionOptions& o) {
  const int nx = full.numStates();
  const Eigen::PartialPivLU<Eigen::MatrixXd> Elu(full.E);
  const Eigen::MatrixXd At = Elu.solve(full.A), Bt = Elu.solve(full.B);
  Eigen::EigenSolver<Eigen::MatrixXd> es(At);
  if (es.info() != Eigen::Success) throw NumericalError("modal reduction: eigen solution of the state matrix failed");
  const Eigen::VectorXcd lambda = es.eigenvalues();
  const Eigen::MatrixXcd V = es.eigenvectors();
  const Eigen::MatrixXcd W = V.inverse();  // rows: left eigenvectors, W V = I
  // Modes: one per real eigenvalue, one per complex pair (the member with Im > 0).
  struct ModeRef {
    int index;
    bool pair;
    double magnitude;
    Eigen::MatrixXd residue;  ///< |C_o v| |w B_i| / |lambda| per output-input pair.
  };
  std::vector<ModeRef> modes;
  Eigen::MatrixXd pair_max = Eigen::MatrixXd::Zero(full.C.rows(), full.B.cols());
  for (int i = 0; i < nx; ++i) {
    const double im = lambda[i].imag();
    if (im < -1e-12 * std::abs(lambda[i])) continue;
    const Eigen::VectorXd cv = (full.C.cast<cd>() * V.col(i)).cwiseAbs();
    const Eigen::RowVectorXd wb = (W.row(i) * Bt.cast<cd>()).cwiseAbs();
    const Eigen::MatrixXd r = cv * wb / std::max(std::abs(lambda[i]), 1e-300);
    pair_max = pair_max.cwiseMax(r);
    modes.push_back({i, im > 1e-12 * std::abs(lambda[i]), std::abs(lambda[i]), r});
  }
  int unseen = 0;
  if (o.drop_unseen && pair_max.size()) {
    // A mode is seen when some pair gets at least 1e-9 of that pair's largest modal
    // contribution (pairs that are zero by symmetry are measured against 1e-12 of the
    // model's largest, so their round-off sees nothing).
    const Eigen::MatrixXd floor = (1e-9 * pair_max).cwiseMax(1e-12 * pair_max.maxCoeff());
    std::vector<ModeRef> seen;
    for (const auto& m : modes) ((m.residue - floor).maxCoeff() >= 0 ? seen.push_back(m) : void(++unseen));
    modes.swap(seen);
  }
  std::stable_sort(modes.begin(), modes.end(), [](const ModeRef& a, const ModeRef& b) { return a.magnitude < b.magnitude; });
  std::vector<ModeRef> kept;
  if (o.modes > 0) {
    // Count oscillatory modes (complex pairs); real roots (overdamped modes, relaxation)
    // are kept when they lie within the range of the kept pairs.
    double reach = 0;
    int counted = 0;
    for (const auto& m : modes)
      if (m.pair && counted < o.modes) {
        reach = m.magnitude;
        ++counted;
      }
    counted = 0;
    for (const auto& m : modes) {
      if (m.pair ? counted++ < o.modes : m.magnitude <= reach) kept.push_back(m);
    }
  } else {
    for (const auto& m : modes) {
      const double f = m.magnitude / (2 * M_PI);
      if (f >= o.band_min_hz && f <= o.band_max_hz) kept.push_back(m);
    }
  }
  std::vector<Eigen::VectorXd> right, left;
  for (const auto& m : kept) {
    right.push_back(V.col(m.index).real());
    left.push_back(W.row(m.index).real().transpose());
    if (m.pair) {
      right.push_back(V.col(m.index).imag());
      left.push_back(W.row(m.index).imag().transpose());
    }
  }
  const int nr = static_cast<int>(right.size());
  Eigen::MatrixXd T(nx, nr), L(nr, nx);
  for (int k = 0; k < nr; ++k) {
    T.col(k) = right[k];
    L.row(k) = left[k].transpose();
  }
  ReducedModel red;
  StateSpace& r = red.model;
  r.E = L * T;
  r.A = L * At * T;
  r.B = L * Bt;
  r.C = full.C * T;
  r.D = full.D;
  r.input_names = full.input_names;
  r.input_units = full.input_units;
  r.output_names = full.output_names;
  r.output_units = full.output_units;
  for (int k = 0; k < nr; ++k) r.state_names.push_back("modal" + std::to_string(k + 1));
  red.kept_modes = static_cast<int>(kept.size());
  red.discarded_modes = static_cast<int>(modes.size() - kept.size()) + unseen;
  red.unseen_modes = unseen;
  for (const auto& m : kept) red.kept_frequencies_hz.push_back(m.magnitude / (2 * M_PI));
  if (o.residualize && red.discarded_modes > 0) {
    const Eigen::FullPivLU<Eigen::MatrixXd> a_full(full.A);
    if (!a_full.isInvertible())
      throw NumericalError("static residualization needs a model without rigid-body modes (the state matrix is singular)");
    const Eigen::MatrixXd h_full = -full.C * a_full.solve(full.B) + full.D;
    Eigen::MatrixXd h_kept = r.D;
    if (nr > 0) {
      const Eigen::FullPivLU<Eigen::MatrixXd> a_red(r.A);
      if (!a_red.isInvertible()) throw NumericalError("static residualization: a kept mode has a zero eigenvalue");
      h_kept = -r.C * a_red.solve(r.B) + r.D;
    }
    r.D += h_full - h_kept;
    red.residualized = true;
  }
  return red;
}

ModelError compareResponses(const StateSpace& a, const StateSpace& b, const std::vector<double>& omegas) {
  const Eigen::Index no = a.C.rows(), ni = a.B.cols();
  Eigen::MatrixXd diff = Eigen::MatrixXd::Zero(no, ni), peak = Eigen::MatrixXd::Zero(no, ni);
  for (double w : omegas) {
    const Eigen::MatrixXcd ha = a.response(w), hb = b.response(w);
    diff = diff.cwiseMax((ha - hb).cwiseAbs());
    peak = peak.cwiseMax(ha.cwiseAbs());
  }
  // A pair that is zero up to round-off (a pinned point's response) is measured against
  // the model's largest response instead, so its noise is not reported as an error.
  ModelError e;
  const double floor = 1e-9 * (peak.size() ? peak.maxCoeff() : 0.0);
  e.relative = diff.cwiseQuotient(peak.cwiseMax(std::max(floor, 1e-300)));
  e.max_relative = e.relative.size() ? e.relative.maxCoeff() : 0.0;
  return e;
}

Eigen::VectorXcd polesFromIntegratorJacobian(const StateSpace& m, double c) {
  const Eigen::MatrixXd Jp = m.E - c * m.A, Jm = m.E + c * m.A;  // J(c), J(-c)
  // J(-c) v = Lambda J(c) v. J(c) is invertible unless a pole sits at 1/c, so the
  // pencil is solved as the standard problem J(c)^-1 J(-c) (Eigen's real QZ solver
  // lost the large eigenvalues here).
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(Jp);
  if (!lu.isInvertible()) throw NumericalError("integrator Jacobian J(dCoef) is singular: a pole sits at 1/dCoef");
  Eigen::EigenSolver<Eigen::MatrixXd> es(lu.solve(Jm), false);
  const Eigen::VectorXcd Lambda = es.eigenvalues();
  Eigen::VectorXcd lambda(Lambda.size());
  for (Eigen::Index i = 0; i < Lambda.size(); ++i) lambda[i] = (Lambda[i] - 1.0) / (c * (Lambda[i] + 1.0));
  return lambda;
}

}  // namespace mmv

#include "sim/hamsas/hamsas_modes.hpp"

#include <cmath>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

const char* kDirections[6] = {"x", "y", "z", "rx", "ry", "rz"};

/// A rigid motion pattern over the free coordinates: component `dof` of every body in
/// `groups`, scaled per group.
Eigen::VectorXd pattern(const SpatialSpec& s, const std::map<std::string, double>& groups, int dof) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(6 * (static_cast<int>(s.bodies.size()) - 1));
  for (std::size_t b = 1; b < s.bodies.size(); ++b) {
    auto it = groups.find(s.bodies[b].group);
    if (it != groups.end()) v[SpatialLinearization::row(static_cast<int>(b)) + dof] = it->second;
  }
  return v;
}

}  // namespace

const std::vector<std::pair<std::string, double>>& hamsasMeasuredFeatures() {
  static const std::vector<std::pair<std::string, double>> f = {
      {"IP (horizontal)", 0.065},     {"DOF cross-coupling", 0.125},   {"MGAS vertical", 0.100},
      {"horizontal GAS", 0.265},      {"little pendulums", 22.0},      {"effective spherical joints", 60.0}};
  return f;
}

namespace {

double measured(const std::string& feature) {
  for (const auto& [name, hz] : hamsasMeasuredFeatures())
    if (name == feature) return hz;
  throw InternalError("no measured feature " + feature);
}

/// Kinetic energy shares per group and direction, strain shares per element group,
/// and a label (the group and direction that carry the most).
SpatialMode describeMode(const SpatialSpec& s, const SpatialLinearization& lin, const Eigen::VectorXd& phi, double frequency_hz) {
  SpatialMode m;
  m.frequency_hz = frequency_hz;
  const double T = phi.dot(lin.M * phi);
  std::map<std::string, Eigen::Matrix<double, 6, 1>> by_dir;
  for (std::size_t b = 1; b < s.bodies.size(); ++b) {
    const int r = SpatialLinearization::row(static_cast<int>(b));
    const Eigen::VectorXd pb = phi.segment<6>(r);
    const Eigen::Matrix<double, 6, 6> Mb = lin.M.block<6, 6>(r, r);
    m.kinetic_share[s.bodies[b].group] += pb.dot(Mb * pb) / T;
    auto& d = by_dir.try_emplace(s.bodies[b].group, Eigen::Matrix<double, 6, 1>::Zero()).first->second;
    for (int k = 0; k < 6; ++k) d[k] += pb[k] * (Mb.row(k).dot(pb));
  }
  // Shares of the elastic energy (each element's is >= 0), and the preloads' work apart:
  // as shares of the net energy an IP mode read flex_joint=10003% preload=-9910%.
  double elastic = 0, preload = 0;
  for (const auto& e : lin.elements) elastic += phi.dot(e.K * phi), preload += phi.dot(e.K_preload * phi);
  for (const auto& e : lin.elements)
    if (elastic > 0) m.strain_share[e.group] += phi.dot(e.K * phi) / elastic;
  m.preload_over_elastic = elastic > 0 ? preload / elastic : 0.0;
  std::string best;
  double share = -1;
  const auto groups = m.kinetic_share;
  for (const auto& [g, d] : by_dir)
    for (int k = 0; k < 6; ++k) m.kinetic_share[g + "." + kDirections[k]] = d[k] / T;
  for (const auto& [g, v] : groups)
    if (v > share) share = v, best = g;
  Eigen::Index k;
  by_dir[best].maxCoeff(&k);
  m.label = best + " " + kDirections[k];
  return m;
}

/// The measured features matched to modes: by correlation with a rigid pattern (IP,
/// tilt, vertical, GAS) or by the first mode with half its energy in a group.
void matchFeatures(const HamsasSpec& spec, HamsasModes& h) {
  const SpatialSpec& s = h.model;
  const SpatialLinearization& lin = h.lin;
  const ModalSolution& sol = h.solution;
  const int nm = static_cast<int>(sol.omega2.size());
  auto correlate = [&](const Eigen::VectorXd& v, int i) {
    const Eigen::VectorXd phi = sol.shapes.col(i);
    const double num = phi.dot(lin.M * v);
    return num * num / (phi.dot(lin.M * phi) * v.dot(lin.M * v));
  };
  const double m_ot = s.bodies[s.output_body].mass, m_sb = spec.sb_mass;
  auto byPattern = [&](const std::string& feature, double measured, const Eigen::VectorXd& v, const std::string& rule) {
    FeatureMatch f{feature, measured, 0, std::nullopt, 0, rule};
    for (int i = 0; i < nm; ++i) {
      if (!sol.isStable(i) || sol.isRigidBody(i)) continue;
      const double c = correlate(v, i);
      if (c > f.shape_match) f.shape_match = c, f.mode = ModeNumber::atIndex(i);
    }
    if (f.mode) f.model_hz = h.modes[f.mode->index()].frequency_hz;
    h.features.push_back(f);
  };
  auto byShare = [&](const std::string& feature, double measured, const std::string& rule, auto share) {
    FeatureMatch f{feature, measured, 0, std::nullopt, 0, rule};
    for (int i = 0; i < nm && !f.mode; ++i)
      if (sol.isStable(i) && !sol.isRigidBody(i) && share(h.modes[i]) >= 0.5) {
        f.mode = ModeNumber::atIndex(i);
        f.shape_match = share(h.modes[i]);
        f.model_hz = h.modes[i].frequency_hz;
      }
    h.features.push_back(f);
  };
  const std::map<std::string, double> stack = {{"ot", 1.0}, {"sb", 1.0}, {"lp", 1.0}};
  const std::map<std::string, double> gas = {{"ot", 1.0}, {"sb", -m_ot / m_sb}, {"lp", -m_ot / m_sb}};
  const std::map<std::string, double> table = {{"ot", 1.0}};
  for (int d = 0; d < 2; ++d)
    byPattern(std::string("IP (horizontal) ") + kDirections[d], measured("IP (horizontal)"), pattern(s, stack, d),
              std::string("spring box, table and little pendulums translating together in ") + kDirections[d]);
  for (int d = 3; d < 5; ++d)
    byPattern(std::string("DOF cross-coupling ") + kDirections[d], measured("DOF cross-coupling"), pattern(s, table, d),
              std::string("optical table tilting (") + kDirections[d] + ") on the MGAS springs");
  byPattern("MGAS vertical", measured("MGAS vertical"), pattern(s, table, 2), "optical table translating in z on the MGAS springs");
  for (int d = 0; d < 2; ++d)
    byPattern(std::string("horizontal GAS ") + kDirections[d], measured("horizontal GAS"), pattern(s, gas, d),
              std::string("optical table against the spring box in ") + kDirections[d] + ", zero momentum");
  byShare("little pendulums", measured("little pendulums"),
          "lowest mode with >= 50 % of its kinetic energy in the IP legs rocking (rx, ry) and the little pendulums",
          [](const SpatialMode& m) {
            auto get = [&](const char* g) { auto it = m.kinetic_share.find(g); return it == m.kinetic_share.end() ? 0.0 : it->second; };
            return get("ip_leg.rx") + get("ip_leg.ry") + get("lp");
          });
  byShare("effective spherical joints", measured("effective spherical joints"), "lowest mode with >= 50 % of its strain energy in the joint springs' elasticity",
          [](const SpatialMode& m) {
            auto it = m.strain_share.find("joint");
            return it == m.strain_share.end() ? 0.0 : it->second;
          });
}

}  // namespace

void describeModes(HamsasModes& h) {
  h.modes.clear();
  for (int i = 0; i < static_cast<int>(h.solution.omega2.size()); ++i)
    h.modes.push_back(describeMode(h.model, h.lin, h.solution.shapes.col(i), h.solution.frequencyHz(i)));
}

HamsasModes analyseHamsas(const HamsasSpec& spec) {
  HamsasModes h;
  h.spec = spec;
  h.model = buildHamsas(spec);
  h.lin = linearizeSpatial(h.model, spec.ideal_joints);
  h.solution = spatialModes(h.lin);
  const SpatialLinearization& lin = h.lin;
  const ModalSolution& sol = h.solution;
  describeModes(h);
  for (int i = 0; i < static_cast<int>(sol.omega2.size()); ++i) {
    const Eigen::VectorXd phi = sol.shapes.col(i);
    if (sol.isStable(i) && !sol.isRigidBody(i)) {
      const Eigen::VectorXd eta = lin.Z.transpose() * phi;
      const Eigen::VectorXd mv = lin.Mz * eta;
      h.max_relative_residual =
          std::max(h.max_relative_residual, (lin.Kz * eta - sol.omega2[i] * mv).norm() / (sol.omega2[i] * mv.norm()));
    }
  }
  matchFeatures(spec, h);
  return h;
}

std::vector<Eigen::MatrixXcd> hamsasTransmissibility(const HamsasModes& h, const std::vector<double>& f) {
  std::vector<Eigen::MatrixXcd> out;
  out.reserve(f.size());
  for (double fi : f) out.push_back(spatialTransmissibility(h.model, h.lin, 2 * M_PI * fi));
  return out;
}

StateSpace hamsasControlModel(const HamsasModes& h) {
  const Eigen::MatrixXd S = spatialSensorMatrix(h.model) * h.lin.Z;
  const Eigen::MatrixXd none;
  StateSpace ss = secondOrderModel(h.lin.Mz, h.lin.Cz, h.lin.Kz, S.transpose(), S, none, none, none);
  for (const auto& r : h.model.sensors) {
    ss.input_names.push_back("actuator_" + r.name);
    ss.input_units.push_back("N");
    ss.output_names.push_back("sensor_" + r.name);
    ss.output_units.push_back("m");
  }
  const int nz = static_cast<int>(h.lin.Z.cols());
  const bool plain = h.lin.Z.cols() == h.lin.Z.rows();
  for (int i = 0; i < nz; ++i) {
    std::string name = "eta" + std::to_string(i + 1);
    if (plain) name = h.model.bodies[i / 6 + 1].name + "." + kDirections[i % 6];
    ss.state_names.push_back(name);
  }
  for (int i = 0; i < nz; ++i) ss.state_names.push_back(ss.state_names[i] + "_dot");
  return ss;
}

std::vector<HamsasVaryPoint> varyHamsas(const HamsasSpec& base, const std::string& key, const std::vector<double>& values,
                                        const std::vector<double>& f) {
  const HamsasParameter* param = nullptr;
  std::string known;
  for (const HamsasParameter& p : hamsasParameters()) {
    if (key == p.key) param = &p;
    known += (known.empty() ? "" : ", ") + std::string(p.key);
  }
  if (!param) throw std::invalid_argument("unknown HAM-SAS parameter '" + key + "' (known: " + known + ")");
  auto db = [](std::complex<double> v) { return 20 * std::log10(std::abs(v) + 1e-300); };
  std::vector<HamsasVaryPoint> out;
  for (double x : values) {
    HamsasSpec spec = base;
    spec.*param->field = x;
    const HamsasModes hv = analyseHamsas(spec);  // buildHamsas refuses non-physical values
    auto at = [&](double hz, int k) { return db(spatialTransmissibility(hv.model, hv.lin, 2 * M_PI * hz)(k, k)); };
    HamsasVaryPoint p;
    p.value = x;
    p.ip_hz = hv.features.front().model_hz;
    p.x_at_1hz_db = at(1, 0);
    p.x_at_3hz_db = at(3, 0);
    p.x_at_10hz_db = at(10, 0);
    p.z_at_10hz_db = at(10, 2);
    for (const auto& Ti : hamsasTransmissibility(hv, f)) p.x_db.push_back(db(Ti(0, 0)));
    out.push_back(std::move(p));
  }
  return out;
}

}  // namespace mmv

#include "sim/modes/sensor_loading.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "sim/core/errors.hpp"
#include "sim/core/progress.hpp"

namespace mmv {

std::pair<ModeNumber, double> followMode(const Eigen::MatrixXd& M, const Eigen::VectorXd& phi, const Eigen::MatrixXd& loaded) {
  const Eigen::VectorXd Mphi = M * phi;
  std::pair<ModeNumber, double> best{ModeNumber(1), 0.0};
  for (Eigen::Index k = 0; k < loaded.cols(); ++k) {
    const Eigen::VectorXd psi = loaded.col(k);
    const double mac = std::pow(Mphi.dot(psi), 2) / (phi.dot(Mphi) * psi.dot(M * psi));
    if (mac > best.second) best = {ModeNumber::atIndex(static_cast<int>(k)), mac};
  }
  return best;
}

ArticleScene sceneWithSensors(const ArticleScene& scene, const PlacementStudy& study, double mass) {
  ArticleScene loaded = scene;
  for (int b : study.result.kept_blocks) {
    const PlacementCandidate& c = study.candidates[static_cast<std::size_t>(b)];
    if (c.fixed) continue;
    auto link = std::find_if(loaded.article.links.begin(), loaded.article.links.end(), [&](const LinkSpec& l) { return l.name == c.link; });
    MMV_DEMAND(link != loaded.article.links.end());
    link->station_masses.push_back({c.x_m, mass});
  }
  return loaded;
}

namespace {
constexpr double kFollowReach = 1.5;  ///< loaded modes up to this multiple of the target's frequency
constexpr double kLostMac = 0.5;      ///< below it no loaded mode is the target's
}  // namespace

void firstOrderLoading(const PlacementStudy& study, double sensor_mass_kg, SensorLoading& out) {
  MMV_DEMAND(sensor_mass_kg > 0);
  out.sensor_mass_kg = sensor_mass_kg;
  out.modes.assign(study.target_modes.size(), {});
  for (int b : study.result.kept_blocks) {
    const PlacementCandidate& c = study.candidates[static_cast<std::size_t>(b)];
    if (c.fixed) continue;
    ++out.sensors;
    for (std::size_t j = 0; j < out.modes.size(); ++j) {
      const auto& u = c.shape[j];
      out.modes[j].first_order -= 0.5 * sensor_mass_kg * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    }
  }
  out.added_kg = sensor_mass_kg * out.sensors;
}

void followLoadedModes(const PlacementStudy& study, const Eigen::MatrixXd& M, const Eigen::MatrixXd& shapes,
                       const ModalSolution& loaded, SensorLoading& out) {
  MMV_DEMAND(out.modes.size() == study.target_modes.size() && shapes.cols() == static_cast<Eigen::Index>(out.modes.size()));
  for (std::size_t j = 0; j < study.target_modes.size(); ++j) {
    SensorLoading::Mode& m = out.modes[j];
    m.mode = study.target_modes[j];
    m.frequency_hz = study.target_frequencies_hz[j];
    // Added mass lowers every frequency (Rayleigh); the sensors' weight changes the
    // geometric stiffness by a few per cent. A loaded mode far above the target is a
    // local mode of a heavy sensor on a light piece, never its counterpart.
    Eigen::Index reach = 1;
    while (reach < loaded.shapes.cols() && loaded.frequencyHz(static_cast<int>(reach)) <= kFollowReach * m.frequency_hz) ++reach;
    std::tie(m.loaded_mode, m.mac) = followMode(M, shapes.col(static_cast<Eigen::Index>(j)), loaded.shapes.leftCols(reach));
    m.lost = m.mac < kLostMac;
    m.loaded_hz = loaded.frequencyHz(m.loaded_mode.index());
    m.shift = m.loaded_hz / m.frequency_hz - 1;
    m.beyond_first_order = std::abs(m.shift - m.first_order) > 0.2 * std::abs(m.shift) + 1e-6;
  }
  for (auto& a : out.modes)
    for (const auto& b : out.modes)
      if (&a != &b && a.loaded_mode == b.loaded_mode) a.shared = true;
}

SensorLoading sensorLoading(const ArticleScene& scene, const SolvedScene& s, const Eigen::MatrixXd& shapes,
                            const PlacementStudy& study, double sensor_mass_kg) {
  MMV_DEMAND(sensor_mass_kg > 0 && shapes.cols() == static_cast<Eigen::Index>(study.target_modes.size()));
  const ProgressStage stage("the sensors' masses on the model: its modes again");
  SensorLoading out;
  firstOrderLoading(study, sensor_mass_kg, out);
  const ArticleScene loaded = sceneWithSensors(scene, study, sensor_mass_kg);
  int highest = 0;
  for (const ModeNumber m : study.target_modes) highest = std::max(highest, m.number());
  const SolvedScene l = solveScene(loaded, {}, std::min<int>(highest + 6, static_cast<int>(s.modes.omega2.size())));
  MMV_DEMAND(l.linearized.dofs == s.linearized.dofs);  // welded masses add no coordinate
  followLoadedModes(study, s.linearized.M, shapes, l.modes, out);
  return out;
}

}  // namespace mmv

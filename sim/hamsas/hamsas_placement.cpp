#include "sim/hamsas/hamsas_placement.hpp"

#include <cmath>

#include "sim/core/text.hpp"

namespace mmv {

PlacementProblem hamsasCandidates(const HamsasModes& h, const std::vector<ModeNumber>& targets, bool triaxial,
                                  std::vector<PlacementCandidate>& candidates) {
  const int k = static_cast<int>(targets.size());
  PlacementProblem p;
  p.omega.resize(k);
  for (int j = 0; j < k; ++j) p.omega[j] = 2 * M_PI * h.solution.frequencyHz(targets[j].index());
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> masses;
  const char* axes[3] = {"x", "y", "z"};
  for (std::size_t b = 1; b < h.model.bodies.size(); ++b) {
    const SpatialBody& body = h.model.bodies[b];
    const Eigen::Vector3d half = 0.5 * equivalentBox(body);
    const int r = SpatialLinearization::row(static_cast<int>(b));
    for (int c = -1; c < 8; ++c) {  // -1: the mass centre; 0..7: the box's corners
      const Eigen::Vector3d offset = c < 0 ? Eigen::Vector3d::Zero()
                                           : Eigen::Vector3d((c & 1) ? half.x() : -half.x(), (c & 2) ? half.y() : -half.y(),
                                                             (c & 4) ? half.z() : -half.z());
      const std::string name = c < 0 ? body.name + ".com" : strf("%s.corner%d", body.name.c_str(), c + 1);
      const Eigen::Vector3d at = body.com + offset;
      // Each target mode's translation there: the body's translation plus its small rotation x offset.
      Eigen::MatrixXd u(3, k);
      for (int j = 0; j < k; ++j) {
        const Eigen::VectorXd phi = h.solution.shapes.col(targets[j].index());
        u.col(j) = phi.segment<3>(r) + phi.segment<3>(r + 3).cross(offset);
      }
      for (int a = 0; a < 3; ++a) {
        rows.push_back(u.row(a));
        masses.push_back(body.mass / 9);
        if (!triaxial || a == 0) candidates.push_back({name, body.name, 0.0, triaxial ? "triaxial" : axes[a], at.x(), at.y(), at.z()});
        p.block.push_back(static_cast<int>(candidates.size()) - 1);
      }
    }
  }
  p.phi.resize(static_cast<Eigen::Index>(rows.size()), k);
  for (std::size_t i = 0; i < rows.size(); ++i) p.phi.row(static_cast<Eigen::Index>(i)) = rows[i];
  p.row_mass = Eigen::Map<Eigen::VectorXd>(masses.data(), static_cast<Eigen::Index>(masses.size()));
  return p;
}

PlacementStudy runHamsasPlacement(const HamsasScene& scene, const HamsasModes& h, const PlacementOptions& o) {
  PlacementStudy study;
  study.scene_name = scene.name;
  study.method = placementMethodName(o.method);
  study.triaxial = o.triaxial;
  study.target_modes = placementTargets(h.solution, o);
  for (const ModeNumber m : study.target_modes) study.target_frequencies_hz.push_back(h.solution.frequencyHz(m.index()));
  const PlacementProblem p = hamsasCandidates(h, study.target_modes, o.triaxial, study.candidates);
  choosePlacement(study, p, o, 3, "the centre and 8 corners of each of " + std::to_string(h.model.bodies.size() - 1) + " bodies");
  return study;
}

}  // namespace mmv

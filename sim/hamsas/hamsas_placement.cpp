#include "sim/hamsas/hamsas_placement.hpp"

#include <cmath>

#include "sim/core/text.hpp"
#include "sim/core/errors.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/modes/sensor_loading.hpp"
#include "sim/modes/tam.hpp"

namespace mmv {

namespace {

/// The test-analysis models on the chosen sensor directions (`readings`: each candidate
/// direction's reading per unit free coordinate, the kept blocks' rows in row order),
/// over the admissible coordinates (Z: ideal joints' null space; the identity for stiff
/// ones), as the article's (sim/modes/place_sensors.cpp).
void buildHamsasTams(PlacementStudy& study, const HamsasModes& h, const std::vector<int>& block,
                     const std::vector<Eigen::RowVectorXd>& readings, const std::vector<TamMethod>& methods) {
  std::vector<char> kept(study.candidates.size(), 0);
  for (int b : study.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  std::vector<Eigen::Index> chosen;
  std::vector<int> seen_in_block(study.candidates.size(), 0);  // a triaxial block's rows are x, y, z
  for (std::size_t r = 0; r < readings.size(); ++r) {
    const auto b = static_cast<std::size_t>(block[r]);
    const int within = seen_in_block[b]++;
    if (!kept[b]) continue;
    chosen.push_back(static_cast<Eigen::Index>(r));
    const PlacementCandidate& c = study.candidates[b];
    study.channels.push_back(c.station + " " + (study.triaxial ? std::string(1, "xyz"[within]) : c.axis));
  }
  const SpatialLinearization& lin = h.lin;
  const Eigen::Index n = lin.M.rows();
  const Eigen::MatrixXd Z = lin.Z.size() ? lin.Z : Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd P(static_cast<Eigen::Index>(chosen.size()), n), phi(n, static_cast<Eigen::Index>(study.target_modes.size()));
  for (std::size_t i = 0; i < chosen.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = readings[static_cast<std::size_t>(chosen[i])];
  TamInput in{Z.transpose() * lin.M * Z, Z.transpose() * lin.K * Z, {}, {}, {}};
  in.P = P * Z;
  in.omega2.resize(static_cast<Eigen::Index>(study.target_modes.size()));
  for (std::size_t j = 0; j < study.target_modes.size(); ++j) {
    phi.col(static_cast<Eigen::Index>(j)) = h.solution.shapes.col(study.target_modes[j].index());
    in.omega2[static_cast<Eigen::Index>(j)] = h.solution.omega2[study.target_modes[j].index()];
  }
  in.phi = Z.transpose() * phi;
  for (const TamMethod m : methods) study.tams.push_back(buildTam(in, m));
}

}  // namespace

int hamsasNode(int body, int point) { return body * 100 + point + 1; }

PlacementProblem hamsasCandidates(const HamsasModes& h, const std::vector<ModeNumber>& targets, bool triaxial,
                                  std::vector<PlacementCandidate>& candidates, std::vector<Eigen::RowVectorXd>* readings,
                                  const SpatialSpec* points) {
  const SpatialSpec& geometry = points ? *points : h.model;
  MMV_DEMAND(geometry.bodies.size() == h.model.bodies.size());
  const int k = static_cast<int>(targets.size());
  PlacementProblem p;
  p.omega.resize(k);
  for (int j = 0; j < k; ++j) p.omega[j] = 2 * M_PI * h.solution.frequencyHz(targets[j].index());
  std::vector<Eigen::RowVectorXd> rows;
  std::vector<double> masses;
  const char* axes[3] = {"x", "y", "z"};
  for (std::size_t b = 1; b < h.model.bodies.size(); ++b) {
    const SpatialBody& body = geometry.bodies[b];
    const Eigen::Vector3d half = 0.5 * equivalentBox(body);
    const int r = SpatialLinearization::row(static_cast<int>(b));
    for (int c = -1; c < 8; ++c) {  // -1: the mass centre; 0..7: the box's corners
      const Eigen::Vector3d corner = c < 0 ? Eigen::Vector3d::Zero()
                                           : Eigen::Vector3d((c & 1) ? half.x() : -half.x(), (c & 2) ? half.y() : -half.y(),
                                                             (c & 4) ? half.z() : -half.z());
      const std::string name = c < 0 ? body.name + ".com" : strf("%s.corner%d", body.name.c_str(), c + 1);
      const Eigen::Vector3d at = body.com + corner;
      // From the mass centre of `h`'s body, where its coordinates are.
      const Eigen::Vector3d offset = at - h.model.bodies[b].com;
      // Each target mode's translation there: the body's translation plus its small rotation x offset.
      Eigen::MatrixXd u(3, k);
      for (int j = 0; j < k; ++j) {
        const Eigen::VectorXd phi = h.solution.shapes.col(targets[j].index());
        u.col(j) = phi.segment<3>(r) + phi.segment<3>(r + 3).cross(offset);
      }
      for (int a = 0; a < 3; ++a) {
        rows.push_back(u.row(a));
        if (readings) {  // along axis a per unit free coordinate: e_a . t + w . (offset x e_a)
          Eigen::RowVectorXd reading = Eigen::RowVectorXd::Zero(h.solution.shapes.rows());
          reading(r + a) = 1;
          reading.segment<3>(r + 3) = offset.cross(Eigen::Vector3d::Unit(a)).transpose();
          readings->push_back(std::move(reading));
        }
        masses.push_back(h.model.bodies[b].mass / 9);
        if (!triaxial || a == 0) {
          PlacementCandidate cand;
          cand.station = name;
          cand.link = body.name;
          cand.axis = triaxial ? "triaxial" : axes[a];
          cand.world_x = at.x(), cand.world_y = at.y(), cand.world_z = at.z();
          cand.node = hamsasNode(static_cast<int>(b), c);
          for (int j = 0; j < k; ++j) cand.shape.push_back({u(0, j), u(1, j), u(2, j)});
          candidates.push_back(std::move(cand));
        }
        p.block.push_back(static_cast<int>(candidates.size()) - 1);
      }
    }
  }
  p.phi.resize(static_cast<Eigen::Index>(rows.size()), k);
  for (std::size_t i = 0; i < rows.size(); ++i) p.phi.row(static_cast<Eigen::Index>(i)) = rows[i];
  p.row_mass = Eigen::Map<Eigen::VectorXd>(masses.data(), static_cast<Eigen::Index>(masses.size()));
  return p;
}

SpatialSpec isolatorWithSensors(const SpatialSpec& model, const PlacementStudy& study, double mass) {
  SpatialSpec loaded = model;
  for (int b : study.result.kept_blocks) {
    const PlacementCandidate& c = study.candidates[static_cast<std::size_t>(b)];
    const int index = model.bodyIndex(c.link);
    MMV_DEMAND(index > 0);
    SpatialBody& body = loaded.bodies[static_cast<std::size_t>(index)];
    const Eigen::Vector3d p(c.world_x, c.world_y, c.world_z);
    const double total = body.mass + mass;
    const Eigen::Vector3d com = (body.mass * body.com + mass * p) / total;
    // Both inertias about the new mass centre (parallel axes).
    auto shift = [](double m, const Eigen::Vector3d& d) {
      return Eigen::Matrix3d(m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
    };
    body.inertia += shift(body.mass, body.com - com) + shift(mass, p - com);
    body.mass = total;
    body.com = com;
  }
  return loaded;
}

SensorLoading hamsasSensorLoading(const HamsasModes& h, const PlacementStudy& study, double sensor_mass_kg) {
  SensorLoading out;
  out.weight_in_stiffness = true;
  firstOrderLoading(study, sensor_mass_kg, out);
  const HamsasModes carrying = isolatorCarrying(h, study, sensor_mass_kg);
  const SpatialSpec& model = carrying.model;
  ModalSolution loaded = carrying.solution;
  // The loaded coordinates are each body's motion at its new mass centre c': the motion
  // at the old one c is t + w x (c - c'), so the shapes compare over the same coordinates.
  for (std::size_t b = 1; b < model.bodies.size(); ++b) {
    const Eigen::Vector3d d = h.model.bodies[b].com - model.bodies[b].com;
    const int r = SpatialLinearization::row(static_cast<int>(b));
    for (Eigen::Index k = 0; k < loaded.shapes.cols(); ++k) {
      const Eigen::Vector3d w = loaded.shapes.col(k).segment<3>(r + 3);
      loaded.shapes.col(k).segment<3>(r) += w.cross(d);
    }
  }
  Eigen::MatrixXd shapes(h.solution.shapes.rows(), static_cast<Eigen::Index>(study.target_modes.size()));
  for (std::size_t j = 0; j < study.target_modes.size(); ++j)
    shapes.col(static_cast<Eigen::Index>(j)) = h.solution.shapes.col(study.target_modes[j].index());
  followLoadedModes(study, h.lin.M, shapes, loaded, out);
  return out;
}

HamsasModes isolatorCarrying(const HamsasModes& h, const PlacementStudy& study, double mass) {
  HamsasModes loaded;
  loaded.spec = h.spec;
  loaded.model = isolatorWithSensors(h.model, study, mass);
  loaded.lin = linearizeSpatial(loaded.model, h.spec.ideal_joints);
  loaded.solution = spatialModes(loaded.lin);
  describeModes(loaded);
  return loaded;
}

namespace {

/// One placement on the isolator `h`, at the points of the bare isolator `bare`'s bodies.
PlacementStudy placeOnIsolator(const HamsasScene& scene, const HamsasModes& h, const SpatialSpec& bare, const PlacementOptions& o) {
  PlacementStudy study;
  study.scene_name = scene.name;
  study.method = placementMethodName(o.method);
  study.triaxial = o.triaxial;
  study.target_modes = placementTargets(h.solution, o);
  for (const ModeNumber m : study.target_modes) study.target_frequencies_hz.push_back(h.solution.frequencyHz(m.index()));
  std::vector<Eigen::RowVectorXd> readings;
  PlacementProblem p = hamsasCandidates(h, study.target_modes, o.triaxial, study.candidates, &readings, &bare);
  keepChosenSet(o, study, p);
  // Each point's three rows are x, y and z, in that order (hamsasCandidates).
  for (std::size_t r = 0; r < p.block.size(); ++r)
    study.directions.push_back({p.block[r], std::string(1, "xyz"[r % 3]),
                                {r % 3 == 0 ? 1.0 : 0.0, r % 3 == 1 ? 1.0 : 0.0, r % 3 == 2 ? 1.0 : 0.0}});
  choosePlacement(study, p, o, 3, "the centre and 8 corners of each of " + std::to_string(h.model.bodies.size() - 1) + " bodies");
  if (!o.tam.empty()) buildHamsasTams(study, h, p.block, readings, o.tam);
  return study;
}

}  // namespace

PlacementStudy runHamsasPlacement(const HamsasScene& scene, const HamsasModes& h, const PlacementOptions& o) {
  MMV_DEMAND(!o.iterate_loaded || o.sensor_mass_kg > 0);
  const PlacementStudy bare = placeOnIsolator(scene, h, h.model, o);
  if (o.sensor_mass_kg == 0) return bare;
  std::vector<LoadedIteration> iterations;
  PlacementStudy chosen = !o.iterate_loaded ? bare : placeOnLoadedModel(bare, [&](const PlacementStudy& carried, bool keep) {
    PlacementOptions on_loaded = o;
    if (keep) on_loaded.keep_set = chosenSet(carried);
    return placeOnIsolator(scene, isolatorCarrying(h, carried, o.sensor_mass_kg), h.model, on_loaded);
  }, iterations);
  chosen.loading = hamsasSensorLoading(h, withChosenSet(bare, chosen), o.sensor_mass_kg);
  chosen.loading->iterations = iterations;
  return chosen;
}

}  // namespace mmv

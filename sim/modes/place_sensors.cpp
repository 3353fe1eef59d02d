#include "sim/modes/place_sensors.hpp"
#include "sim/core/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <optional>

#include "article/section.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/sensor_loading.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/stations.hpp"

namespace mmv {
namespace {

}  // namespace

std::vector<ModeNumber> placementTargets(const ModalSolution& modes, const PlacementOptions& o) {
  std::vector<ModeNumber> out;
  const int n = static_cast<int>(modes.omega2.size());
  if (o.modes.empty()) {
    for (int i = 0; i < n; ++i)
      if (modes.isStable(i) && !modes.isRigidBody(i) && modes.frequencyHz(i) < o.below_hz) out.push_back(ModeNumber::atIndex(i));
    if (out.empty()) throw OptionError("--below-hz", ": no vibration mode below " + std::to_string(o.below_hz) + " Hz");
    return out;
  }
  for (const ModeNumber m : o.modes) {
    const std::string named = ": mode " + std::to_string(m.number());
    if (m.index() < 0 || m.index() >= n)
      throw OptionError("--modes", named + " does not exist (the model has " + std::to_string(n) + ")");
    if (!modes.isStable(m.index()) || modes.isRigidBody(m.index()))
      throw OptionError("--modes", named + " is not a vibration mode (rigid or unstable)");
    out.push_back(m);
  }
  return out;
}

void choosePlacement(PlacementStudy& study, const PlacementProblem& p, const PlacementOptions& o, int directions,
                     const std::string& where) {
  const int blocks = static_cast<int>(study.candidates.size()), k = static_cast<int>(study.target_modes.size());
  if (o.count < 1 || o.count > blocks)
    throw OptionError("--count", " " + std::to_string(o.count) + ": there are " + std::to_string(blocks) + " candidate " +
                     (o.triaxial ? "blocks" : "sensors") + " (" + where + ")");
  if (o.method == PlacementMethod::EffectiveIndependence && (o.triaxial ? directions * o.count : o.count) < k)
    throw OptionError("--count", " " + std::to_string(o.count) + ": effective independence needs at least one measured direction per target mode (" +
                     std::to_string(k) + ")");
  study.result = placeSensors(p, o.method, o.count);
  study.requested = o.count;
}

namespace {

/// Candidate stations of one link: every spacing out to the tip, the tip included.
std::vector<double> stationsAlong(double length, double spacing) {
  std::vector<double> x;
  for (int k = 1; k * spacing < length - 1e-9 * length; ++k) x.push_back(k * spacing);
  x.push_back(length);
  return x;
}

}  // namespace

namespace {

/// Every candidate direction's rows, as the stations add them.
struct StationRows {
  std::vector<Eigen::RowVectorXd> rows;      ///< over the target modes
  std::vector<Eigen::RowVectorXd> readings;  ///< over the coordinates
  std::vector<std::string> names;            ///< "station axis"
  std::vector<double> masses;
};

/// What a station's rows are computed from.
struct StationView {
  const PointRef& ref;
  const SimTK::State& st;
  const std::vector<int>& dofs;
  const Eigen::MatrixXd& shapes;  ///< coordinates x target modes
  int directions;
  bool triaxial;
};

/// Adds station `c` (its name, link, x, mass and node set): its candidate(s), one row per
/// measuring direction (axial, transverse, and normal on the spatial model).
void addStation(PlacementStudy& study, PlacementProblem& p, StationRows& acc, const StationView& v, PlacementCandidate c) {
  static const char* const axis_names[] = {"axial", "transverse", "normal"};
  // directions x k: the world translations
  const Eigen::MatrixXd J = v.ref.translationJacobian(v.st, v.dofs, v.directions), u = J * v.shapes;
  const SimTK::Vec3 pos = v.ref.position(v.st);
  c.world_x = pos[0], c.world_y = pos[1], c.world_z = pos[2];
  for (Eigen::Index j = 0; j < u.cols(); ++j) c.shape.push_back({u(0, j), u(1, j), v.directions == 3 ? u(2, j) : 0.0});
  for (int a = 0; a < v.directions; ++a) {
    const SimTK::Vec3 e = v.ref.localAxis(v.st, a);
    Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(u.cols()), reading = Eigen::RowVectorXd::Zero(J.cols());
    for (int d = 0; d < v.directions; ++d) row += e[d] * u.row(d), reading += e[d] * J.row(d);
    acc.rows.push_back(row);
    acc.readings.push_back(reading);
    acc.names.push_back(c.station + " " + axis_names[a]);
    acc.masses.push_back(c.mass_kg);
    if (!v.triaxial || a == 0) {
      c.axis = v.triaxial ? "triaxial" : axis_names[a];
      study.candidates.push_back(c);
    }
    const int block = static_cast<int>(study.candidates.size()) - 1;
    p.block.push_back(block);
    study.directions.push_back({block, axis_names[a], {e[0], e[1], e[2]}});
    if (p.block_at.size() < study.candidates.size()) p.block_at.push_back(Eigen::Vector3d(pos[0], pos[1], pos[2]));
  }
}

/// Whether station x of `link` lies in one of the keep-out stretches (a span [x, x_end]
/// when it touches one).
bool keptOut(const PlacementOptions& o, const std::string& link, double x, double x_end = -1) {
  const double hi = std::max(x, x_end);
  return std::any_of(o.keep_out.begin(), o.keep_out.end(),
                     [&](const PlacementOptions::KeepOut& k) { return k.link == link && hi >= k.from_m && x <= k.to_m; });
}

/// The strain candidates (PlacementOptions::strain_span_m): on every flexible link, spans
/// of that length from the root every `spacing`, each one block and one row, the mean
/// surface strain over it per unit modal coordinate (frf's and modes' strain row,
/// strainRow, from the stations' interpolated rotations: no mesh in it), measuring along
/// the link's axis at the span's middle, where its node sits. On the spatial model each
/// span is two candidates, the +y face's bending in the plane and the +z face's out of
/// it (named A:B:out; a link kept planar in it has the first only); both may be chosen (co-located blocks never conflict: the faces
/// do not overlap).
void addStrainCandidates(const ArticleScene& scene, const Model& model, const SimTK::State& st, const SolvedScene& s,
                         const Eigen::MatrixXd& shapes, const PlacementOptions& o, PlacementStudy& study, PlacementProblem& p,
                         StationRows& acc) {
  const double L = o.strain_span_m;
  const bool spatial = scene.article.model == ArticleModel::Spatial;
  auto station = [](const std::string& link, double x) { return strf("%s@%.6gm", link.c_str(), x); };
  for (std::size_t li = 0; li < scene.article.links.size(); ++li) {
    const LinkSpec& link = scene.article.links[li];
    if (link.rigid) continue;
    const Material& mat = *scene.article.findMaterial(link.material);
    const double rho_a = mat.density * sectionArea(*scene.article.findSection(link.section));
    for (int i = 0; i * o.spacing_m + L <= link.length * (1 + 1e-12); ++i) {
      const double xa = i * o.spacing_m, xb = std::min(xa + L, link.length), mid = 0.5 * (xa + xb);
      if (keptOut(o, link.name, xa, xb)) continue;
      const std::string a = station(link.name, xa), b = station(link.name, xb);
      std::string error;
      const std::optional<PointRef> ra = PointRef::resolve(model, scene.article, a, error),
                                    rb = PointRef::resolve(model, scene.article, b, error),
                                    rm = PointRef::resolve(model, scene.article, station(link.name, mid), error);
      MMV_DEMAND(ra && rb && rm);
      for (const bool out : spatial && scene.article.bendsOutOfPlane(link) ? std::vector<bool>{false, true} : std::vector<bool>{false}) {
        std::string why;
        const std::optional<StrainSpan> span = strainSpan(scene.article, a, b, why, out);
        if (!span) throw OptionError("--strain-span", strf(" %g: link %s cannot carry one: %s", L, link.name.c_str(), why.c_str()));
        const Eigen::RowVectorXd reading = strainRow(*ra, *rb, st, s.linearized.dofs, span->surface_m / (xb - xa), out);
        PlacementCandidate c{a + ":" + b + (out ? ":out" : ""), link.name, mid, "strain", 0, 0, 0, rho_a * (xb - xa),
                             static_cast<int>(li + 1) * 100000 + static_cast<int>(std::lround(1e3 * mid)), {}};
        const SimTK::Vec3 pos = rm->position(st), e = rm->localAxis(st, 0);
        c.world_x = pos[0], c.world_y = pos[1], c.world_z = pos[2];
        const Eigen::MatrixXd u = rm->translationJacobian(st, s.linearized.dofs, spatial ? 3 : 2) * shapes;  // the middle's motion, for the drawings
        for (Eigen::Index j = 0; j < u.cols(); ++j) c.shape.push_back({u(0, j), u(1, j), spatial ? u(2, j) : 0.0});
        const Eigen::RowVectorXd row = reading * shapes;
        c.strain.assign(row.data(), row.data() + row.size());
        study.candidates.push_back(c);
        const int block = static_cast<int>(study.candidates.size()) - 1;
        acc.rows.push_back(row);
        acc.readings.push_back(reading);
        acc.names.push_back(c.station + " strain");
        acc.masses.push_back(c.mass_kg);
        p.block.push_back(block);
        p.block_at.push_back(Eigen::Vector3d(pos[0], pos[1], pos[2]));
        study.directions.push_back({block, "strain", {e[0], e[1], e[2]}});
      }
    }
  }
  if (study.candidates.empty())
    throw OptionError("--strain-span", strf(" %g: no flexible link is that long (or the keep-outs cover every span)", L));
}

/// The chosen sensor directions (the kept blocks' rows, in row order).
void chosenChannels(PlacementStudy& study, const std::vector<int>& block, const std::vector<std::string>& names) {
  std::vector<char> kept(study.candidates.size(), 0);
  for (int b : study.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  for (std::size_t r = 0; r < names.size(); ++r)
    if (kept[static_cast<std::size_t>(block[r])]) study.channels.push_back(names[r]);
}

/// The TAMs on the chosen sensor directions (the kept blocks' rows, in row order), over
/// the model's admissible coordinates (Z: a closed loop's; the identity for a tree).
void buildPlacementTams(PlacementStudy& study, const SolvedScene& s, const Eigen::MatrixXd& shapes,
                        const std::vector<int>& block, const std::vector<Eigen::RowVectorXd>& readings,
                        const std::vector<TamMethod>& methods) {
  const ProgressStage stage("test-analysis models on the chosen sensors");
  std::vector<char> kept(study.candidates.size(), 0);
  for (int b : study.result.kept_blocks) kept[static_cast<std::size_t>(b)] = 1;
  std::vector<Eigen::Index> chosen;
  for (std::size_t r = 0; r < readings.size(); ++r)
    if (kept[static_cast<std::size_t>(block[r])]) chosen.push_back(static_cast<Eigen::Index>(r));
  const LinearizedModel& lin = s.linearized;
  const Eigen::Index n = lin.M.rows();
  const Eigen::MatrixXd Z = lin.Z.size() ? lin.Z : Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd P(static_cast<Eigen::Index>(chosen.size()), n);
  for (std::size_t i = 0; i < chosen.size(); ++i) P.row(static_cast<Eigen::Index>(i)) = readings[static_cast<std::size_t>(chosen[i])];
  TamInput in{Z.transpose() * lin.M * Z, Z.transpose() * lin.K * Z, P * Z, Z.transpose() * shapes, {}};
  in.omega2.resize(static_cast<Eigen::Index>(study.target_modes.size()));
  for (std::size_t j = 0; j < study.target_modes.size(); ++j)
    in.omega2[static_cast<Eigen::Index>(j)] = s.modes.omega2[study.target_modes[j].index()];
  for (const TamMethod m : methods) study.tams.push_back(buildTam(in, m));
}

/// The scene's own accelerometers, fixed in advance (`keep_scene_sensors`): each one's
/// direction at a candidate station already there (same link, same distance), else at a
/// station of its own added with its other directions as candidates.
void fixScenesSensors(const ArticleScene& scene, const Model& model, const SimTK::State& st, const SolvedScene& s,
                      const Eigen::MatrixXd& shapes, bool triaxial, PlacementStudy& study, PlacementProblem& p, StationRows& acc) {
  static const char* const axis_names[] = {"axial", "transverse", "normal"};
  int fixed = 0;
  for (const auto& sensor : scene.sensors) {
    if (sensor.type != "accelerometer") continue;
    std::string why;
    const auto at = pointAlongLink(scene.article, sensor.target, why);
    if (!at) throw OptionError("--keep-scene-sensors", ": sensor " + sensor.name + " (" + sensor.where + "): " + why);
    auto same = [&](const PlacementCandidate& c) { return c.link == at->first && std::abs(c.x_m - at->second) < 1e-9; };
    if (std::none_of(study.candidates.begin(), study.candidates.end(), same)) {
      std::string error;
      const std::optional<PointRef> ref = PointRef::resolve(model, scene.article, sensor.target, error);
      MMV_DEMAND(ref.has_value());  // the reader resolved it
      const auto li = std::find_if(scene.article.links.begin(), scene.article.links.end(), [&](const LinkSpec& l) { return l.name == at->first; });
      const int node = static_cast<int>(li - scene.article.links.begin() + 1) * 100000 + static_cast<int>(std::lround(1e3 * at->second));
      addStation(study, p, acc, {*ref, st, s.linearized.dofs, shapes, model.isSpatial() ? 3 : 2, triaxial},
                 PlacementCandidate{sensor.target, at->first, at->second, "", 0, 0, 0, 0.0, node, {}});
    }
    for (std::size_t r = 0; r < study.directions.size(); ++r) {
      const PlacementDirection& d = study.directions[r];
      if (!same(study.candidates[static_cast<std::size_t>(d.block)]) || d.axis != axis_names[sensor.axis]) continue;
      p.fixed_block.resize(study.candidates.size(), 0);
      fixed += !p.fixed_block[static_cast<std::size_t>(d.block)];
      p.fixed_block[static_cast<std::size_t>(d.block)] = 1;
      study.candidates[static_cast<std::size_t>(d.block)].fixed = true;
    }
  }
  if (fixed == 0) throw OptionError("--keep-scene-sensors", ": the scene has no accelerometer to keep (sensors: of type accelerometer)");
  p.fixed_block.resize(study.candidates.size(), 0);
}

/// One placement on `scene`, solved as `s`; its target shapes into `shapes`.
PlacementStudy placeOn(const ArticleScene& scene, const PlacementOptions& o, const SolvedScene& s, Eigen::MatrixXd& shapes_out) {
  MMV_DEMAND(o.spacing_m > 0);
  const Model& model = *s.model;
  SimTK::State st = s.equilibrium.state;
  model.getSystem().realize(st, SimTK::Stage::Position);
  PlacementStudy study;
  study.scene_name = scene.name;
  study.method = placementMethodName(o.method);
  study.triaxial = o.triaxial;
  study.target_modes = placementTargets(s.modes, o);
  const int k = static_cast<int>(study.target_modes.size());
  Eigen::MatrixXd shapes(s.modes.shapes.rows(), k);
  PlacementProblem p;
  p.omega.resize(k);
  for (int j = 0; j < k; ++j) {
    shapes.col(j) = s.modes.shapes.col(study.target_modes[j].index());
    study.target_frequencies_hz.push_back(s.modes.frequencyHz(study.target_modes[j].index()));
    p.omega[j] = 2 * M_PI * study.target_frequencies_hz.back();
  }
  StationRows acc;
  // The spatial model adds each station's normal axis (out of the plane).
  const int directions = model.isSpatial() ? 3 : 2;
  const ProgressStage stage("candidate stations: their mode shapes");
  if (o.strain_span_m > 0) addStrainCandidates(scene, model, st, s, shapes, o, study, p, acc);
  for (std::size_t li = 0; li < scene.article.links.size() && o.strain_span_m == 0; ++li) {
    const LinkSpec& link = scene.article.links[li];
    const Material& mat = *scene.article.findMaterial(link.material);
    const double rho_a = mat.density * sectionArea(*scene.article.findSection(link.section));
    // The lumped masses at the link's tip: its tip mass and the torquers of the joints it carries.
    double tip = link.tip_mass ? link.tip_mass->mass : 0.0;
    for (const auto& j : scene.article.joints)
      if (j.parent == link.name && j.torquer) tip += j.torquer->mass;
    const std::vector<double> xs = stationsAlong(link.length, o.spacing_m);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const double x = xs[i];
      if (keptOut(o, link.name, x)) continue;
      // Each station's tributary mass (modal kinetic energy): the link between the
      // midpoints to its neighbours (the first from the root, the last to the tip), and
      // the tip's lumped masses at the last. Before, every station had rho A spacing and
      // no torquer or tip mass counted.
      const double from = i == 0 ? 0.0 : 0.5 * (xs[i - 1] + x), to = i + 1 == xs.size() ? link.length : 0.5 * (x + xs[i + 1]);
      const double mass = rho_a * (to - from) + (i + 1 == xs.size() ? tip : 0.0);
      char name[96];
      std::snprintf(name, sizeof name, "%s@%.4gm", link.name.c_str(), x);
      if (std::strtod(std::strchr(name, '@') + 1, nullptr) > link.length)  // rounded past the tip: exact digits
        std::snprintf(name, sizeof name, "%s@%.17gm", link.name.c_str(), x);
      std::string error;
      const std::optional<PointRef> ref = PointRef::resolve(model, scene.article, name, error);
      MMV_DEMAND(ref.has_value());
      PlacementCandidate c{name, link.name, x, "", 0, 0, 0, mass, static_cast<int>(li + 1) * 100000 + static_cast<int>(std::lround(1e3 * x)), {}};
      addStation(study, p, acc, {*ref, st, s.linearized.dofs, shapes, directions, o.triaxial}, c);
    }
  }
  if (o.keep_scene_sensors) {
    fixScenesSensors(scene, model, st, s, shapes, o.triaxial, study, p, acc);
    const long fixed = std::count(p.fixed_block.begin(), p.fixed_block.end(), 1);
    if (o.count < fixed)
      throw OptionError("--count", strf(" %d: below the %ld accelerometers of the scene that --keep-scene-sensors keeps", o.count, fixed));
  }
  keepChosenSet(o, study, p);
  // Films or gauges do not overlap on the link's face: their middles at least a span
  // apart (a part in 1e6 less, for the sag's and the stations' rounding).
  p.min_separation = std::max(o.min_separation_m, o.strain_span_m * (1 - 1e-6));
  const std::vector<Eigen::RowVectorXd>& rows = acc.rows;
  const std::vector<double>& masses = acc.masses;
  p.phi.resize(rows.size(), k);
  for (std::size_t r = 0; r < rows.size(); ++r) p.phi.row(r) = rows[r];
  p.row_mass = Eigen::Map<const Eigen::VectorXd>(masses.data(), static_cast<Eigen::Index>(masses.size()));
  choosePlacement(study, p, o, directions, "spacing " + std::to_string(o.spacing_m) + " m");
  chosenChannels(study, p.block, acc.names);
  if (!o.tam.empty()) buildPlacementTams(study, s, shapes, p.block, acc.readings, o.tam);
  study.instrument = o.instrument;
  study.strain = o.strain_span_m > 0;
  study.strain_span_m = o.strain_span_m;
  shapes_out = shapes;
  return study;
}

}  // namespace

std::vector<std::string> chosenSet(const PlacementStudy& s) {
  std::vector<std::string> out;
  for (int b : s.result.kept_blocks) {
    const PlacementCandidate& c = s.candidates[static_cast<std::size_t>(b)];
    out.push_back(c.station + " " + c.axis);
  }
  std::sort(out.begin(), out.end());
  return out;
}

namespace {

/// The Fisher determinant det(A^T A) of the set `names` ("station axis", sorted) on
/// `s`'s model: A's rows are each of its directions' target shapes (as placeSensors
/// builds them: the candidate's translations along the direction), 0 when singular.
double fisherDeterminantOf(const PlacementStudy& s, const std::vector<std::string>& names) {
  const Eigen::Index k = static_cast<Eigen::Index>(s.target_modes.size());
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(k, k);
  for (const PlacementDirection& d : s.directions) {
    const PlacementCandidate& c = s.candidates[static_cast<std::size_t>(d.block)];
    if (!std::binary_search(names.begin(), names.end(), c.station + " " + c.axis)) continue;
    Eigen::RowVectorXd row(k);
    for (Eigen::Index j = 0; j < k; ++j) {
      const auto& u = c.shape[static_cast<std::size_t>(j)];
      row[j] = d.world[0] * u[0] + d.world[1] * u[1] + d.world[2] * u[2];
    }
    Q += row.transpose() * row;
  }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(Q).singularValues();
  return !sv.size() || !(sv[sv.size() - 1] > 1e-14 * sv[0]) ? 0.0 : sv.prod();
}

}  // namespace

void keepChosenSet(const PlacementOptions& o, const PlacementStudy& study, PlacementProblem& p) {
  if (o.keep_set.empty()) return;
  p.fixed_block.resize(study.candidates.size(), 0);
  for (const std::string& name : o.keep_set) {
    const auto at = std::find_if(study.candidates.begin(), study.candidates.end(),
                                 [&](const PlacementCandidate& c) { return c.station + " " + c.axis == name; });
    MMV_DEMAND(at != study.candidates.end());
    p.fixed_block[static_cast<std::size_t>(at - study.candidates.begin())] = 1;
  }
}

PlacementStudy placeOnLoadedModel(const PlacementStudy& bare,
                                  const std::function<PlacementStudy(const PlacementStudy&, bool)>& placeCarrying,
                                  std::vector<LoadedIteration>& iterations) {
  PlacementStudy chosen = bare;
  std::vector<std::vector<std::string>> seen{chosenSet(bare)};
  for (int it = 1; it <= kMaxLoadedIterations; ++it) {
    const ProgressStage stage(strf("placement on the model with the sensors: pass %d", it));
    PlacementStudy next = placeCarrying(chosen, false);
    const std::vector<std::string> set = chosenSet(next);
    LoadedIteration step;
    step.pass = it;
    for (const auto& name : set) step.changed += !std::binary_search(seen.back().begin(), seen.back().end(), name);
    if (step.changed > 0) {  // the set its model carried, on that model: as informative?
      const double mine = next.result.fisher_determinant, carried = fisherDeterminantOf(next, seen.back());
      step.tie = mine > 0 && std::abs(carried - mine) <= kTiedInformation * mine;
    }
    step.settled = step.changed == 0 || step.tie;
    step.repeats = !step.settled && std::find(seen.begin(), seen.end(), set) != seen.end();
    iterations.push_back(step);
    // A tie keeps the set the model carried, evaluated on that model.
    chosen = step.tie ? placeCarrying(chosen, true) : std::move(next);
    chosen.carried = seen.back();
    if (step.settled || step.repeats) break;
    seen.push_back(set);
  }
  return chosen;
}

PlacementStudy withNamedSet(const PlacementStudy& s, const std::vector<std::string>& names) {
  PlacementStudy out = s;
  out.result.kept_blocks.clear();
  for (const std::string& name : names) {
    const auto same = std::find_if(s.candidates.begin(), s.candidates.end(),
                                   [&](const PlacementCandidate& d) { return d.station + " " + d.axis == name; });
    MMV_DEMAND(same != s.candidates.end());
    out.result.kept_blocks.push_back(static_cast<int>(same - s.candidates.begin()));
  }
  return out;
}

PlacementStudy withChosenSet(const PlacementStudy& bare, const PlacementStudy& chosen) {
  std::vector<std::string> names;  // in chosen's order
  for (int b : chosen.result.kept_blocks)
    names.push_back(chosen.candidates[static_cast<std::size_t>(b)].station + " " + chosen.candidates[static_cast<std::size_t>(b)].axis);
  return withNamedSet(bare, names);
}

PlacementStudy runPlacement(const ArticleScene& scene, const PlacementOptions& o) {
  MMV_DEMAND(!o.iterate_loaded || o.sensor_mass_kg > 0);
  const SolvedScene s = solveScene(scene);
  Eigen::MatrixXd shapes;
  const PlacementStudy bare = placeOn(scene, o, s, shapes);
  if (o.sensor_mass_kg == 0) return bare;
  std::vector<LoadedIteration> iterations;
  PlacementStudy chosen = !o.iterate_loaded ? bare : placeOnLoadedModel(bare, [&](const PlacementStudy& carried, bool keep) {
    const ArticleScene loaded = sceneWithSensors(scene, carried, o.sensor_mass_kg);
    PlacementOptions on_loaded = o;
    if (keep) on_loaded.keep_set = chosenSet(carried);
    Eigen::MatrixXd loaded_shapes;
    return placeOn(loaded, on_loaded, solveScene(loaded), loaded_shapes);
  }, iterations);
  // The loading of the final set, against the article without it.
  chosen.loading = sensorLoading(scene, s, shapes, withChosenSet(bare, chosen), o.sensor_mass_kg);
  chosen.loading->iterations = iterations;
  return chosen;
}

}  // namespace mmv

#include "sim/linear/correlation.hpp"

#include <limits>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/model/stations.hpp"
#include "sim/statics/statics.hpp"
#include "sim/scene/stations.hpp"

namespace mmv {

std::string stationOfNode(const ArticleSpec& article, int node) {
  const int link = node / 100000, mm = node % 100000;
  if (node <= 0 || link < 1 || link > static_cast<int>(article.links.size())) return "";
  const LinkSpec& l = article.links[static_cast<std::size_t>(link - 1)];
  if (mm > std::lround(1e3 * l.length)) return "";
  return mm == std::lround(1e3 * l.length) ? l.name + ".tip" : strf("%s@%.3fm", l.name.c_str(), 1e-3 * mm);
}


double modalAssurance(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) {
  MMV_DEMAND(a.size() == b.size());
  const double na = a.squaredNorm(), nb = b.squaredNorm();
  if (!(na > 0) || !(nb > 0)) return std::numeric_limits<double>::quiet_NaN();  // undefined, not "no correlation"
  return std::norm(a.dot(b)) / (na * nb);  // dot() conjugates its first argument
}

double frequencyResponseAssurance(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b) {
  MMV_DEMAND(a.size() == b.size());
  std::complex<double> cross = 0;
  double na = 0, nb = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    cross += std::conj(a[k]) * b[k];
    na += std::norm(a[k]);
    nb += std::norm(b[k]);
  }
  if (!(na > 0) || !(nb > 0)) return 0.0;
  return std::norm(cross) / (na * nb);
}

std::vector<ModePair> pairByMac(const Eigen::MatrixXd& mac, double threshold,
                                const Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>& allowed) {
  MMV_DEMAND(allowed.size() == 0 || (allowed.rows() == mac.rows() && allowed.cols() == mac.cols()));
  std::vector<ModePair> all, out;
  for (Eigen::Index i = 0; i < mac.rows(); ++i)
    for (Eigen::Index j = 0; j < mac.cols(); ++j)
      if (mac(i, j) >= threshold && (allowed.size() == 0 || allowed(i, j))) all.push_back({static_cast<int>(i), static_cast<int>(j), mac(i, j)});
  std::stable_sort(all.begin(), all.end(), [](const ModePair& a, const ModePair& b) { return a.mac > b.mac; });
  std::set<int> rows, cols;
  for (const auto& p : all)
    if (!rows.count(p.test) && !cols.count(p.model)) {
      rows.insert(p.test);
      cols.insert(p.model);
      out.push_back(p);
    }
  std::sort(out.begin(), out.end(), [](const ModePair& a, const ModePair& b) { return a.test < b.test; });
  return out;
}

namespace {

double distance(const SimTK::Vec3& p, const std::array<double, 3>& x) {
  return std::sqrt(std::pow(p[0] - x[0], 2) + std::pow(p[1] - x[1], 2) + std::pow(p[2] - x[2], 2));
}

/// The station of the article nearest to x at the equilibrium: sampled along every
/// link, then refined by golden-section search around the nearest sample.
std::pair<std::string, double> nearestStation(const Model& model, const SimTK::State& st, const ArticleSpec& article,
                                              const std::array<double, 3>& x) {
  auto at = [&](const LinkSpec& l, double s) {  // a station built directly: no name to write and parse
    return distance(StationPoint(model, StationSpec{"", l.name, s, 0, 0}).position(st), x);
  };
  std::string best_link;
  double best_s = 0, best_d = INFINITY;
  constexpr int kSamples = 100;
  for (const auto& l : article.links) {
    const double h = l.length / kSamples;
    int k_best = 0;
    double d_best = INFINITY;
    for (int k = 0; k <= kSamples; ++k)
      if (const double d = at(l, std::min(l.length, k * h)); d < d_best) d_best = d, k_best = k;
    double a = std::max(0.0, (k_best - 1) * h), b = std::min(l.length, (k_best + 1) * h);
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    for (int it = 0; it < 40; ++it) {
      const double c = b - g * (b - a), d = a + g * (b - a);
      if (at(l, c) < at(l, d)) b = d;
      else a = c;
    }
    double s = std::floor(0.5 * (a + b) * 1e6) / 1e6;  // to 1 um, never past the tip
    if (s < 1e-5) s = 0;                             // a node at a joint names the link's end exactly
    if (l.length - s < 1e-5) s = l.length;
    // A node at a joint is as near to the links on both sides (to a test's geometry
    // tolerance): the first link in the scene keeps it unless another is nearer by 1 mm.
    constexpr double kJointTie = 1e-3;
    if (const double d = at(l, s); d < best_d - kJointTie || (best_link.empty() && d < best_d))
      best_d = d, best_link = l.name, best_s = s;
  }
  return {strf("%s@%sm", best_link.c_str(), shortest(best_s).c_str()), best_d};
}

std::vector<NodePairing> pairNodes(const ArticleScene& scene, const MeasuredSet& test, const CorrelateOptions& o) {
  // The deflected equilibrium's geometry only: no linearization or modes (runModes makes those).
  const std::unique_ptr<Model> model = buildArticleModel(scene);
  const EquilibriumResult eq = solveEquilibrium(*model);
  if (!eq.converged) throw NumericalError("static equilibrium failed: " + eq.failure);
  SimTK::State st = eq.state;
  model->getSystem().realize(st, SimTK::Stage::Position);
  std::map<int, std::string> named;
  for (const auto& named_pair : o.named_pairs) {
    const int node = named_pair.first;  // a plain variable: C++17 lambdas cannot capture a structured binding (clang)
    const std::string& point = named_pair.second;
    // Both checked by the study (sim/app/correlate_study.cpp) before any model was built.
    MMV_DEMAND(std::any_of(test.nodes.begin(), test.nodes.end(), [&](const MeasuredNode& n) { return n.label == node; }));
    std::string error;
    MMV_DEMAND(PointRef::resolve(*model, scene.article, point, error));
    named[node] = point;
  }
  std::vector<NodePairing> out;
  for (const auto& n : test.nodes) {
    NodePairing p{n.label, n.xyz, "", 0, false, false};
    std::string error;
    const std::string numbered = stationOfNode(scene.article, n.label);
    const std::optional<PointRef> at_number =
        numbered.empty() ? std::nullopt : PointRef::resolve(*model, scene.article, numbered, error);
    if (const auto it = named.find(n.label); it != named.end()) {
      p.station = it->second;
      p.by_name = true;
      p.distance_m = distance(PointRef::resolve(*model, scene.article, it->second, error)->position(st), n.xyz);
    } else if (at_number && distance(at_number->position(st), n.xyz) <= o.pair_distance_m) {
      // mmvlab's own test geometry: the number says which station, the position confirms it
      p.station = numbered;
      p.by_number = true;
      p.distance_m = distance(at_number->position(st), n.xyz);
    } else {
      const auto [station, d] = nearestStation(*model, st, scene.article, n.xyz);
      p.distance_m = d;
      if (d <= o.pair_distance_m) p.station = station;
    }
    out.push_back(p);
  }
  return out;
}

const NodePairing* findNode(const std::vector<NodePairing>& nodes, int label) {
  for (const auto& n : nodes)
    if (n.node == label) return &n;
  return nullptr;
}

/// Pairs r's test and model modes by MAC within the frequency window, and notes each
/// test mode left unpaired whose best MAC lies outside it.
std::vector<ModePair> pairWithinWindow(const CorrelateOptions& o, CorrelationResult& r) {
  // The frequency window: a pair is a pair only where the frequencies are within it.
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> window(r.mac.rows(), r.mac.cols());
  for (Eigen::Index i = 0; i < r.mac.rows(); ++i)
    for (Eigen::Index j = 0; j < r.mac.cols(); ++j) {
      const double ft = r.test_modes[i].frequency_hz, fm = r.model_modes[j].frequency_hz;
      window(i, j) = ft > 0 && std::abs(fm / ft - 1) <= o.max_frequency_error;
    }
  std::vector<ModePair> pairs = pairByMac(r.mac, o.mac_threshold, window);
  for (Eigen::Index i = 0; i < r.mac.rows(); ++i) {
    const bool paired = std::any_of(pairs.begin(), pairs.end(), [&](const ModePair& p) { return p.test == i; });
    Eigen::Index best = -1;
    for (Eigen::Index j = 0; j < r.mac.cols(); ++j)
      if (!window(i, j) && r.mac(i, j) >= o.mac_threshold && (best < 0 || r.mac(i, j) > r.mac(i, best))) best = j;
    if (!paired && best >= 0)
      r.notes.push_back(strf("test mode T%ld (%.4g Hz) has MAC %.3f with model mode M%d (%.4g Hz, %+.0f %%), outside the "
                             "+-%.3g %% frequency window: not paired (--max-frequency-error widens it)",
                             static_cast<long>(i + 1), r.test_modes[i].frequency_hz, r.mac(i, best), r.model_modes[best].number.number(),
                             r.model_modes[best].frequency_hz,
                             100 * (r.model_modes[best].frequency_hz / r.test_modes[i].frequency_hz - 1),
                             100 * o.max_frequency_error));
  }
  return pairs;
}

void correlateModes(const ArticleScene& scene, const CorrelateOptions& o, CorrelationResult& r) {
  std::vector<std::string> stations;
  for (const auto& n : r.nodes)
    if (!n.station.empty() && std::find(stations.begin(), stations.end(), n.station) == stations.end())
      stations.push_back(n.station);
  ModesOptions mo;
  mo.max_modes = o.model_modes;
  mo.with_shapes = false;
  mo.points = stations;
  mo.damping = o.damping;
  ModesReport rep = runModes(scene, mo);
  r.model_modes = rep.modes;
  r.model_damped = rep.damped;
  r.damping_model = rep.damping_model;
  r.mac = Eigen::MatrixXd::Zero(r.test_modes.size(), r.model_modes.size());
  std::set<int> no_geometry;  // shape nodes the file never placed
  for (std::size_t i = 0; i < r.test_modes.size(); ++i) {
    const MeasuredMode& t = r.test_modes[i];
    std::vector<std::complex<double>> tv;
    std::vector<int> at;
    for (std::size_t k = 0; k < t.nodes.size(); ++k) {
      const NodePairing* n = findNode(r.nodes, t.nodes[k]);
      if (!n) {
        no_geometry.insert(t.nodes[k]);
        continue;
      }
      if (n->station.empty()) continue;
      at.push_back(static_cast<int>(std::find(stations.begin(), stations.end(), n->station) - stations.begin()));
      for (int d = 0; d < 3; ++d) tv.push_back(t.shape[k][d]);
    }
    r.shape_dofs = std::max(r.shape_dofs, static_cast<int>(tv.size()));
    const Eigen::VectorXcd a = Eigen::Map<const Eigen::VectorXcd>(tv.data(), static_cast<Eigen::Index>(tv.size()));
    for (std::size_t j = 0; j < r.model_modes.size(); ++j) {
      const ModeInfo& m = r.model_modes[j];
      Eigen::VectorXcd b = Eigen::VectorXcd::Zero(a.size());
      for (std::size_t k = 0; k < at.size(); ++k) {
        b[3 * k] = m.at_points[at[k]].ux;
        b[3 * k + 1] = m.at_points[at[k]].uy;
        b[3 * k + 2] = m.at_points[at[k]].uz;  // 0 on the planar model
      }
      r.mac(i, j) = m.rigid_body || !m.stable ? 0.0 : modalAssurance(a, b);
    }
  }
  for (int node : no_geometry)
    r.notes.push_back(strf("node %d has a mode shape but no geometry (datasets 15, 2411): left out of the MAC", node));
  if (r.shape_dofs == 0 && !r.test_modes.empty())
    r.warnings.push_back("no mode shape has a paired node: every MAC is undefined (the file's shape nodes have no geometry, "
                         "or none lies on the article)");
  for (Eigen::Index i = 0; i < r.mac.rows(); ++i)
    if (r.mac.cols() > 0 && r.mac.row(i).array().isNaN().all() && r.shape_dofs > 0)
      r.warnings.push_back(strf("test mode T%ld does not move at the paired nodes: its MAC is undefined", static_cast<long>(i + 1)));
  r.pairs = pairWithinWindow(o, r);
  std::set<int> paired_test, paired_model;
  for (const auto& p : r.pairs) paired_test.insert(p.test), paired_model.insert(p.model);
  for (std::size_t j = 0; j < r.model_modes.size(); ++j) {
    const ModeInfo& m = r.model_modes[j];
    if (m.stable && !m.rigid_body && m.frequency_hz >= r.band_min_hz && m.frequency_hz <= r.band_max_hz &&
        !paired_model.count(static_cast<int>(j)))
      r.model_not_seen.push_back(static_cast<int>(j));
  }
  for (std::size_t i = 0; i < r.test_modes.size(); ++i)
    if (!paired_test.count(static_cast<int>(i))) r.test_not_predicted.push_back(static_cast<int>(i));
  if (!r.model_modes.empty() && r.model_modes.back().frequency_hz < r.band_max_hz &&
      static_cast<int>(r.model_modes.size()) < rep.model.num_dofs)
    r.warnings.push_back(strf("the model's %zu modes compared reach %.4g Hz, below the test band's top %.4g Hz: raise --modes",
                              r.model_modes.size(), r.model_modes.back().frequency_hz, r.band_max_hz));
}

/// The model's output and input for a measured function, or why it has none.
struct FrfMapping {
  std::optional<OutputSpec> output;
  std::optional<InputSpec> input;
  double sign = 1;
  std::string skipped;
};

FrfMapping mapFrf(const MeasuredFrf& f, const std::vector<NodePairing>& nodes, bool spatial) {
  FrfMapping m;
  // UFF directions 1..6: x, y, z, then rotations about them (axes 0..5); the planar
  // model moves along x, y and about z only.
  const auto modelled = [&](int d) { return d >= 1 && d <= 6 && (spatial || !leavesThePlane(d - 1)); };
  auto station = [&](int node, const char* what) -> std::string {
    const NodePairing* n = findNode(nodes, node);
    if (!n) m.skipped = strf("its %s node %d is not defined in the file", what, node);
    else if (n->station.empty())
      m.skipped = strf("its %s node %d is not on the article (nearest station %.3g m away)", what, node, n->distance_m);
    return n ? n->station : "";
  };
  if (f.function_type != 4 && f.function_type != 5) {
    m.skipped = strf("function type %d is not a frequency response (4) or a transmissibility (5)", f.function_type);
    return m;
  }
  if (f.ordinate_type == 3 || f.ordinate_type == 2) {  // frf writes a strain's (a stress's) response so, direction 0 (a scalar)
    m.skipped = f.ordinate_type == 3 ? "a strain (ordinate type 3): correlate pairs the motions of nodes, not strains"
                                     : "a stress (ordinate type 2): correlate pairs the motions of nodes, not stresses";
    return m;
  }
  const int rd = std::abs(f.response_direction), fd = std::abs(f.reference_direction);
  if (!modelled(rd) || !modelled(fd)) {
    m.skipped = strf("direction %d/%d: %s outside the %s model", f.response_direction, f.reference_direction,
                     spatial ? "directions beyond 6 are" : "z and rotations out of the plane are",
                     spatial ? "spatial" : "planar");
    return m;
  }
  m.sign = (f.response_direction < 0 ? -1 : 1) * (f.reference_direction < 0 ? -1 : 1);
  const bool base = f.denominator_type == 12;
  if (!base && f.denominator_type != 13) {
    m.skipped = strf("denominator type %d: only acceleration (12, of the table) and force (13) are modelled", f.denominator_type);
    return m;
  }
  OutputKind kind;
  const char* kind_name;
  if (f.ordinate_type == 8) kind = OutputKind::Displacement, kind_name = "disp";
  else if (f.ordinate_type == 11) kind = OutputKind::Velocity, kind_name = "vel";
  else if (f.ordinate_type == 12) kind = OutputKind::Acceleration, kind_name = base ? "acc_abs" : "acc";
  else {
    m.skipped = strf("ordinate type %d: only displacement (8), velocity (11) and acceleration (12) are modelled", f.ordinate_type);
    return m;
  }
  const std::string out_point = station(f.response_node, "response");
  if (!m.skipped.empty()) return m;
  const bool absolute = base && kind == OutputKind::Acceleration;
  OutputSpec out;
  out.name = strf("%s:%s:%s", out_point.c_str(), axisName(rd - 1), kind_name);
  out.kind = kind, out.point = out_point, out.axis = rd - 1, out.absolute = absolute;
  m.output = std::move(out);
  if (base) {
    if (fd > 3) {
      m.skipped = strf("direction %d: the table translates only (its inputs are x, y, z)", f.reference_direction);
      return m;
    }
    m.input = InputSpec{std::string("table_") + axisName(fd - 1), InputKind::BaseAcceleration, "", fd - 1};
  } else {
    const std::string in_point = station(f.reference_node, "reference");
    if (!m.skipped.empty()) return {std::nullopt, std::nullopt, 1, m.skipped};
    const bool moment = fd > 3;  // a force at a rotation direction is a moment
    m.input = InputSpec{strf("%s:%s:%s", moment ? "moment" : "force", in_point.c_str(), axisName(fd - 1)),
                        moment ? InputKind::PointMoment : InputKind::PointForce, in_point, fd - 1};
  }
  return m;
}

/// A function the model predicts as zero (below 1e-9 of its largest: a pair the
/// symmetric spatial article decouples) has no FRAC: what the test shows there is an
/// asymmetry the model does not have, and the note says how large it is.
void markDecoupledFrfs(std::vector<FrfCorrelation>& frfs) {
  auto largest = [](const std::vector<std::complex<double>>& v) {
    double m = 0;
    for (const auto& x : v) m = std::max(m, std::abs(x));
    return m;
  };
  double model_max = 0, test_max = 0;
  for (const auto& c : frfs) model_max = std::max(model_max, largest(c.model)), test_max = std::max(test_max, largest(c.test));
  for (auto& c : frfs) {
    if (!c.skipped.empty() || c.model.empty() || largest(c.model) >= 1e-9 * model_max) continue;
    c.skipped = strf("the model predicts no response here (below 1e-9 of its largest function: a decoupled pair); the "
                     "test's is %.3g of the test's largest",
                     test_max > 0 ? largest(c.test) / test_max : 0.0);
    c.frac = 0;
    c.test_peak_hz = c.model_peak_hz = 0;
  }
}

void correlateFrfs(const ArticleScene& scene, const MeasuredSet& test, const CorrelateOptions& o, CorrelationResult& r) {
  std::vector<FrfMapping> maps;
  std::vector<InputSpec> inputs;
  std::vector<OutputSpec> outputs;
  for (const auto& f : test.frfs) {
    maps.push_back(mapFrf(f, r.nodes, scene.article.model == ArticleModel::Spatial));
    const FrfMapping& m = maps.back();
    if (!m.skipped.empty()) continue;
    if (std::none_of(inputs.begin(), inputs.end(), [&](const InputSpec& i) { return i.name == m.input->name; }))
      inputs.push_back(*m.input);
    if (std::none_of(outputs.begin(), outputs.end(), [&](const OutputSpec& x) { return x.name == m.output->name; }))
      outputs.push_back(*m.output);
  }
  std::optional<LinearModel> lm;
  if (!inputs.empty()) lm = buildLinearModel(scene, inputs, outputs, o.damping);
  auto indexOf = [](const auto& list, const std::string& name) {
    return static_cast<Eigen::Index>(std::find_if(list.begin(), list.end(), [&](const auto& x) { return x.name == name; }) -
                                     list.begin());
  };
  std::map<std::vector<double>, std::vector<Eigen::MatrixXcd>> responses;  // per distinct abscissa
  for (std::size_t k = 0; k < test.frfs.size(); ++k) {
    const MeasuredFrf& f = test.frfs[k];
    FrfCorrelation c;
    c.index = static_cast<int>(k);
    c.id = f.id;
    c.skipped = maps[k].skipped;
    if (c.skipped.empty()) {
      c.output = maps[k].output->name;
      c.input = maps[k].input->name;
      std::vector<double> fz;  // the model's response at 0 Hz is its static one, infinite with a free joint: skipped
      for (std::size_t i = 0; i < f.frequency_hz.size(); ++i)
        if (f.frequency_hz[i] > 0) {
          fz.push_back(f.frequency_hz[i]);
          c.test.push_back(f.values[i]);
        }
      auto& h = responses[fz];
      if (h.empty()) {
        std::vector<double> w(fz);
        for (double& x : w) x *= 2 * M_PI;
        h = fullResponses(lm->second_order, w);
      }
      const Eigen::Index o_i = indexOf(lm->outputs, c.output), i_i = indexOf(lm->inputs, c.input);
      for (const auto& hk : h) c.model.push_back(maps[k].sign * hk(o_i, i_i));
      c.frequency_hz = fz;
      c.frac = frequencyResponseAssurance(c.test, c.model);
      auto peak = [&](const std::vector<std::complex<double>>& v) {
        std::size_t b = 0;
        for (std::size_t i = 0; i < v.size(); ++i)
          if (std::abs(v[i]) > std::abs(v[b])) b = i;
        return v.empty() ? 0.0 : fz[b];
      };
      c.test_peak_hz = peak(c.test);
      c.model_peak_hz = peak(c.model);
    }
    r.frfs.push_back(std::move(c));
  }
  markDecoupledFrfs(r.frfs);
}

}  // namespace

CorrelationResult correlate(const ArticleScene& scene, const MeasuredSet& test, const CorrelateOptions& o) {
  if (test.modes.empty() && test.frfs.empty())
    throw SceneError(test.source + ": the file holds no mode shapes (dataset 55) and no functions (58) to correlate");
  if (test.nodes.empty())
    throw SceneError(test.source + ": the file defines no nodes (dataset 15 or 2411), so its points cannot be placed on the article");
  CorrelationResult r;
  r.nodes = pairNodes(scene, test, o);
  if (std::all_of(r.nodes.begin(), r.nodes.end(), [](const NodePairing& n) { return n.station.empty(); })) {
    double nearest = INFINITY;
    for (const auto& n : r.nodes) nearest = std::min(nearest, n.distance_m);
    throw SceneError(strf("%s: no measured node is within %.3g m of the article (the nearest is %.3g m away): is the "
                          "geometry in the scene's frame and in metres (dataset 164)? --pair-distance widens the search",
                          test.source.c_str(), o.pair_distance_m, nearest));
  }
  r.test_modes = test.modes;
  std::sort(r.test_modes.begin(), r.test_modes.end(),
            [](const MeasuredMode& a, const MeasuredMode& b) { return a.frequency_hz < b.frequency_hz; });
  if (!test.frfs.empty()) {
    r.band_min_hz = INFINITY;
    for (const auto& f : test.frfs) {
      r.band_min_hz = std::min(r.band_min_hz, f.frequency_hz.front());
      r.band_max_hz = std::max(r.band_max_hz, f.frequency_hz.back());
    }
  } else {
    r.band_max_hz = 1.1 * r.test_modes.back().frequency_hz;
  }
  correlateModes(scene, o, r);
  correlateFrfs(scene, test, o, r);
  for (const auto& n : r.nodes)
    if (n.station.empty()) r.warnings.push_back(strf("node %d is %.3g m from the article: not paired", n.node, n.distance_m));
  std::map<std::string, std::vector<int>> by_station;
  for (const auto& n : r.nodes)
    if (!n.station.empty()) by_station[n.station].push_back(n.node);
  for (const auto& [station, nodes] : by_station) {
    if (nodes.size() < 2) continue;
    std::string list;
    for (std::size_t k = 0; k < nodes.size(); ++k) list += (k ? ", " : "") + std::to_string(nodes[k]);
    r.notes.push_back(strf("%zu nodes (%s) pair with one station, %s: the model has one motion there (is the test's "
                           "geometry where the article is?)",
                           nodes.size(), list.c_str(), station.c_str()));
  }
  return r;
}

}  // namespace mmv

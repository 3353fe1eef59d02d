#include "sim/app/update_study.hpp"

#include <algorithm>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/update_report.hpp"

namespace mmv::app {
namespace {

SceneSource sourceOf(const LoadedScene& loaded) {
  const std::string& file = std::visit([](const auto& s) -> const std::string& { return s.positions.file; }, loaded.scene);
  const SceneRequest& q = loaded.request;
  return {sceneText(loaded.scene), file, q.sets, sceneFlags(q.segments, q.no_gravity, q.front)};
}

/// One --params entry: KEY or KEY:LO:HI, its nominal the file's plain number.
UpdateParameterSpec parameter(const std::string& spec, const SceneSource& scene, Front front) {
  const std::string opt = optionName(front, "--params") + " " + spec;
  std::vector<std::string> parts;
  std::stringstream ss(spec);
  for (std::string part; std::getline(ss, part, ':');) parts.push_back(part);
  if (!spec.empty() && spec.back() == ':') parts.push_back("");
  if ((parts.size() != 1 && parts.size() != 3) || parts[0].empty())
    throw UsageError(opt + ": expected KEY or KEY:LO:HI (a scene key as --set names it, e.g. "
                           "materials.carbon_carbon.youngs_modulus:35e9:50e9)");
  UpdateParameterSpec p;
  p.key = parts[0];
  for (const auto& set : scene.sets)
    if (set.substr(0, set.find('=')) == p.key)
      throw UsageError(opt + ": also given by --set " + set + ": a parameter starts from the file's value; write that in the file");
  p.where = sceneValueAt(scene.text, scene.sets, p.key);
  if (!p.where.found)
    throw UsageError(opt + ": the scene has no value at " + p.key +
                     " (a key as --set names it: mapping keys and list items by name, e.g. links.link1.tip_mass.mass)");
  if (!p.where.number) throw UsageError(opt + ": " + p.key + " is '" + printable(p.where.text) + "', not a number");
  if (!p.where.in_file || !p.where.plain)
    throw UsageError(opt + ": " + p.key + " is not a plain number written in the scene file (" +
                     (p.where.in_file ? "quoted or a block scalar" : "only a --set patch gives it") +
                     "): update writes the updated scene by changing the file's own values");
  p.nominal = p.where.value;
  if (parts.size() == 3) {
    const std::optional<double> lo = finiteNumber(parts[1]), hi = finiteNumber(parts[2]);
    if (!lo || !hi) throw UsageError(opt + ": LO and HI must be finite numbers");
    p.lower = *lo, p.upper = *hi;
    if (p.lower >= p.upper) throw UsageError(opt + ": LO must be below HI");
    if (p.nominal < p.lower || p.nominal > p.upper)
      throw UsageError(opt + ": the bounds [" + parts[1] + ", " + parts[2] + "] exclude the nominal " + p.where.text +
                       " (line " + std::to_string(p.where.line) + ")");
  } else if (p.nominal == 0) {
    throw UsageError(opt + ": the nominal is 0: give the bounds, " + p.key + ":LO:HI");
  } else {
    p.lower = std::min(p.nominal / 2, 2 * p.nominal), p.upper = std::max(p.nominal / 2, 2 * p.nominal);
  }
  return p;
}

/// Each parameter at each of its bounds and just off its nominal (a count such as
/// `segments` takes whole values only: the fit cannot vary it), the others nominal,
/// through the scene reader.
void checkBoundsReadable(const SceneSource& scene, const std::vector<UpdateParameterSpec>& ps,
                         const std::vector<std::string>& specs, Front front) {
  Eigen::VectorXd p(static_cast<Eigen::Index>(ps.size()));
  for (std::size_t k = 0; k < ps.size(); ++k) p(static_cast<Eigen::Index>(k)) = ps[k].nominal;
  for (std::size_t k = 0; k < ps.size(); ++k)
    for (const double bound : {ps[k].lower, ps[k].upper, ps[k].nominal + 1e-3 * (ps[k].upper - ps[k].nominal)}) {
      Eigen::VectorXd q = p;
      q(static_cast<Eigen::Index>(k)) = bound;
      try {
        sceneAt(scene, ps, q);
      } catch (const SceneError& e) {
        std::string why = e.what();  // the reader names the patch it was given: the user gave the bound
        const std::string patch = "--set " + ps[k].key + "=" + shortest(bound) + ": ";
        if (why.rfind(patch, 0) == 0) why = why.substr(patch.size());
        throw UsageError(optionName(front, "--params") + " " + specs[k] + ": the scene reader refuses " + ps[k].key + " = " +
                         shortest(bound) + ": " + why);
      }
    }
}

struct Checked {
  SceneSource scene;
  std::vector<UpdateParameterSpec> params;
  ModelUpdateOptions options;
  std::optional<CorrelateOptions> pairing;  ///< an article; none: HAM-SAS (the slides' features)
};

Checked checkRequest(const LoadedScene& loaded, const UpdateRequest& r) {
  const Front front = r.pairing.front;
  checkRange(front, "--frequency-sigma", r.frequency_sigma, 1e-6, 1);
  checkRange(front, "--mac-sigma", r.mac_sigma, 1e-6, 1);
  checkRange(front, "--regularization", r.regularization, 0, 1e6);
  checkRange(front, "--max-iterations", r.max_iterations, 1, 1000);
  Checked c{sourceOf(loaded), {}, {}, {}};
  if (const auto* article = std::get_if<ArticleScene>(&loaded.scene)) {
    c.pairing = correlateOptions(r.pairing, *article);
  } else if (!r.pairing.measured.empty()) {
    throw UsageError(optionName(front, "--measured") + " " + r.pairing.measured +
                     ": a HAM-SAS scene is updated against the slides' measured features (docs/hamsas.md), not a file");
  }
  c.options.frequency_sigma = r.frequency_sigma, c.options.mac_sigma = r.mac_sigma;
  // HAM-SAS's shape matches are against the features' model patterns, not measured shapes.
  c.options.mac_residuals = r.mac_residuals && c.pairing.has_value();
  c.options.regularization = r.regularization;
  c.options.max_iterations = r.max_iterations;
  const std::string opt = optionName(front, "--params");
  if (r.params.empty()) throw UsageError(opt + ": name at least one scene key to update (KEY or KEY:LO:HI)");
  if (r.params.size() > static_cast<std::size_t>(kMaxUpdateParameters))
    throw UsageError(strf("%s: %zu parameters, more than the %d one update fits", opt.c_str(), r.params.size(), kMaxUpdateParameters));
  for (const auto& spec : r.params) {
    c.params.push_back(parameter(spec, c.scene, front));
    for (std::size_t k = 0; k + 1 < c.params.size(); ++k)
      if (c.params[k].key == c.params.back().key) throw UsageError(opt + " " + spec + ": " + c.params[k].key + " is named twice");
  }
  checkBoundsReadable(c.scene, c.params, r.params, front);
  return c;
}

/// An article against a measured set: correlate's pairs, redone for every model.
ModelUpdateResult updateArticle(const Checked& c, const MeasuredSet& measured) {
  MeasuredSet modes_only = measured;  // the residuals use the modes; the functions are correlate's
  modes_only.frfs.clear();
  std::vector<TestTarget> targets;
  for (std::size_t i = 0; i < modes_only.modes.size(); ++i) targets.push_back({strf("T%zu", i + 1), modes_only.modes[i].frequency_hz});
  const CorrelateOptions o = *c.pairing;
  const UpdateMatcher match = [&modes_only, &o](const Scene& s) {
    const CorrelationResult cr = correlate(std::get<ArticleScene>(s), modes_only, o);
    std::vector<std::optional<ModelMatch>> out(cr.test_modes.size());
    for (const auto& p : cr.pairs) {
      const ModeInfo& m = cr.model_modes[static_cast<std::size_t>(p.model)];
      out[static_cast<std::size_t>(p.test)] = ModelMatch{m.number, m.frequency_hz, p.mac};
    }
    return out;
  };
  return updateModel(c.scene, c.params, targets, measured.source, match, c.options);
}

/// HAM-SAS against the slides' measured features, each identified by shape in every model.
ModelUpdateResult updateHamsas(const Checked& c, const LoadedScene& loaded) {
  std::vector<TestTarget> targets;
  for (const auto& f : analyseHamsas(std::get<HamsasScene>(loaded.scene).isolator).features) targets.push_back({f.feature, f.measured_hz});
  const UpdateMatcher match = [&targets](const Scene& s) {
    const HamsasModes h = analyseHamsas(std::get<HamsasScene>(s).isolator);
    std::vector<std::optional<ModelMatch>> out(targets.size());
    for (std::size_t t = 0; t < targets.size(); ++t)
      for (const auto& f : h.features)
        if (f.feature == targets[t].label && f.mode) out[t] = ModelMatch{*f.mode, f.model_hz, f.shape_match};
    return out;
  };
  return updateModel(c.scene, c.params, targets, "the HAM-SAS slides' measured features (docs/sources.md section 3)", match,
                     c.options);
}

UpdateStudy finish(ModelUpdateResult result) {
  UpdateStudy s{std::move(result), {}, {}, {}, {}, {}};
  s.json = updateJson(s.result);
  s.text = updateText(s.result);
  s.parameters_csv = updateParametersCsv(s.result);
  s.pairs_csv = updatePairsCsv(s.result);
  s.iterations_csv = updateIterationsCsv(s.result);
  checkResultFinite(s.json);
  return s;
}

}  // namespace

UpdateStudy runUpdateStudy(const LoadedScene& loaded, const UpdateRequest& r) {
  const Checked c = checkRequest(loaded, r);  // every option before the file is read
  if (!c.pairing) return finish(updateHamsas(c, loaded));
  const MeasuredSet test = readMeasuredFile(r.pairing.measured);
  checkNamedPairNodes(test, *c.pairing, r.pairing.front);
  return finish(updateArticle(c, test));
}

UpdateStudy runUpdateStudy(const LoadedScene& loaded, const UpdateRequest& r, const MeasuredSet& measured) {
  const Checked c = checkRequest(loaded, r);
  MMV_DEMAND(c.pairing.has_value());
  checkNamedPairNodes(measured, *c.pairing, r.pairing.front);
  return finish(updateArticle(c, measured));
}

}  // namespace mmv::app

#include "sim/linear/model_update.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {

Scene sceneFromText(const SceneSource& scene, const std::string& text, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = scene.sets;
  sets.insert(sets.end(), extra.begin(), extra.end());
  return parseScene(text, scene.source, sets, scene.flags);
}

/// The comment an updated value carries in the updated scene.
std::string editComment(const UpdatedParameter& u, const std::string& nominal_text) {
  std::string c = "mmvlab update: nominal " + nominal_text + ", updated " + strf("%.6g", u.updated);
  if (!u.determined) c += " (not determined by the data: see the report's identifiability)";
  else if (std::isfinite(u.interval_half_width))
    c += strf(" (95 %% interval %.6g .. %.6g)", u.updated - u.interval_half_width, u.updated + u.interval_half_width);
  else c += " (no interval: no more residuals than parameters)";
  if (u.at_bound) c += strf(", at its bound [%s, %s]", shortest(u.lower).c_str(), shortest(u.upper).c_str());
  return c;
}

double rmsFrequencyError(const std::vector<UpdatePair>& pairs, bool after) {
  double s = 0;
  for (const auto& p : pairs) s += std::pow((after ? p.after_hz : p.before_hz) / p.test_hz - 1, 2);
  return pairs.empty() ? 0 : std::sqrt(s / static_cast<double>(pairs.size()));
}

}  // namespace

Scene sceneAt(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params, const Eigen::VectorXd& p) {
  std::vector<std::string> sets;
  for (std::size_t k = 0; k < params.size(); ++k) sets.push_back(params[k].key + "=" + shortest(p(static_cast<Eigen::Index>(k))));
  return sceneFromText(scene, scene.text, sets);
}

std::optional<Eigen::VectorXd> updateResiduals(const std::vector<TestTarget>& targets,
                                               const std::vector<std::optional<ModelMatch>>& matches,
                                               const std::vector<int>& tracked, const ModelUpdateOptions& o) {
  const Eigen::Index n = static_cast<Eigen::Index>(tracked.size());
  Eigen::VectorXd r(o.mac_residuals ? 2 * n : n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const std::size_t t = static_cast<std::size_t>(tracked[static_cast<std::size_t>(i)]);
    const std::optional<ModelMatch>& m = matches[t];
    if (!m) return std::nullopt;
    r(i) = (m->hz / targets[t].hz - 1) / o.frequency_sigma;
    if (o.mac_residuals) r(n + i) = (1 - m->mac) / o.mac_sigma;
  }
  return r;
}

ModelUpdateResult updateModel(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params,
                              const std::vector<TestTarget>& targets, const std::string& measured_source,
                              const UpdateMatcher& match, const ModelUpdateOptions& o) {
  MMV_DEMAND(!params.empty());
  const Eigen::Index n = static_cast<Eigen::Index>(params.size());
  LeastSquaresProblem problem;
  problem.start.resize(n), problem.lower.resize(n), problem.upper.resize(n), problem.scale.resize(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const UpdateParameterSpec& s = params[static_cast<std::size_t>(k)];
    problem.start(k) = s.nominal, problem.lower(k) = s.lower, problem.upper(k) = s.upper;
    problem.scale(k) = s.nominal != 0 ? std::abs(s.nominal) : s.upper - s.lower;
  }
  problem.regularization = o.regularization;

  ModelUpdateResult out;
  out.options = o;
  out.measured = measured_source;
  const Scene nominal = sceneAt(scene, params, problem.start);
  out.scene = sceneName(nominal);
  out.scene_source = scene.source + overrideSuffix(scene.sets);
  const std::vector<std::optional<ModelMatch>> before = match(nominal);
  MMV_DEMAND(before.size() == targets.size());
  std::vector<int> tracked;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (before[t]) tracked.push_back(static_cast<int>(t));
    else out.notes.push_back(strf("%s (%.4g Hz) is shown by no model mode at the nominal: not in the residuals",
                                  targets[t].label.c_str(), targets[t].hz));
  }
  if (tracked.empty())
    throw SceneError(measured_source + ": no measured mode pairs with a model mode of " + out.scene + ": nothing to update against");

  problem.residuals = [&](const Eigen::VectorXd& p) -> std::optional<Eigen::VectorXd> {
    try {
      return updateResiduals(targets, match(sceneAt(scene, params, p)), tracked, o);
    } catch (const NumericalError&) {  // no equilibrium there: a step not taken
      return std::nullopt;
    } catch (const SceneError&) {  // a combination the reader refuses
      return std::nullopt;
    }
  };
  LeastSquaresOptions lo;
  lo.max_iterations = o.max_iterations;
  out.fit = solveBoundedLeastSquares(problem, lo);
  if (!out.fit.converged)  // no updated scene from a fit that stopped on its way
    throw NumericalError(strf("model updating did not converge in %d iterations (%d model evaluations; the weighted cost "
                              "went from %.6g to %.6g): raise --max-iterations, narrow the bounds or fix a parameter",
                              o.max_iterations, out.fit.evaluations, out.fit.iterations.front().cost, out.fit.cost));

  const Identifiability& id = out.fit.identifiability;
  std::vector<SceneEdit> edits;
  for (Eigen::Index k = 0; k < n; ++k) {
    const UpdateParameterSpec& s = params[static_cast<std::size_t>(k)];
    UpdatedParameter u{s.key, s.where.line, s.nominal, s.lower, s.upper, out.fit.p(k), id.standard_error(k),
                       id.interval_half_width(k), out.fit.at_bound[static_cast<std::size_t>(k)],
                       id.determined[static_cast<std::size_t>(k)]};
    // 10 significant digits: the fit's own to 5e-11, without its round-off's false precision.
    edits.push_back({s.where.offset, s.where.length, strf("%.10g", u.updated), editComment(u, s.where.text)});
    out.parameters.push_back(u);
  }
  out.updated_scene = editedSceneText(scene.text, edits);

  // The "after": the updated file read back, as a user will read it.
  const std::vector<std::optional<ModelMatch>> after = match(sceneFromText(scene, out.updated_scene, {}));
  const std::optional<Eigen::VectorXd> r_after = updateResiduals(targets, after, tracked, o);
  // Equal up to the 10 digits written (a residual moves by at most |J| 1e-10 for them): a
  // value written to the wrong key or misread would move it by orders more.
  if (!r_after || (*r_after - out.fit.residuals).cwiseAbs().maxCoeff() > 1e-6 * (1 + out.fit.residuals.cwiseAbs().maxCoeff()))
    throw InternalError("model updating: the updated scene read back does not reproduce the fit's residuals");
  for (const int t : tracked) {
    const ModelMatch& b = *before[static_cast<std::size_t>(t)];
    const ModelMatch& a = *after[static_cast<std::size_t>(t)];
    out.pairs.push_back({targets[static_cast<std::size_t>(t)].label, targets[static_cast<std::size_t>(t)].hz, b.model, a.model,
                         b.hz, a.hz, b.mac, a.mac});
  }
  out.rms_frequency_error_before = rmsFrequencyError(out.pairs, false);
  out.rms_frequency_error_after = rmsFrequencyError(out.pairs, true);
  return out;
}

}  // namespace mmv

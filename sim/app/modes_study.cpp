#include "sim/app/modes_study.hpp"

#include <algorithm>

#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/finite_check.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/mode_fields.hpp"
#include "sim/io/report.hpp"
#include "sim/io/vtk_export.hpp"
#include "sim/modes/converge.hpp"
#include "sim/plan/check.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::app {

namespace {

void checkRequest(const ModesRequest& r, bool article) {
  checkOptions<ModesParams>(r, r.front);
  const auto opt = [&](const char* key) { return declaredName<ModesParams>(key, r.front); };
  if (!article && (r.target_error > 0 || r.time_budget > 0))
    throw UsageError(opt("target_error") + " applies to the article's scenes (HAM-SAS has no segments)");
  if (r.target_error > 0) {
    if (r.segments_given) throw UsageError(opt("target_error") + " chooses the segments per link: drop " + optionName(r.front, "--segments"));
    if (r.modes == 0)
      throw UsageError(opt("target_error") + " holds the modes shown to it: give " + opt("modes") + " N (N >= 1), not 0");
    if (!r.error_estimate)
      throw UsageError(opt("target_error") + " needs the error estimate: " +
                       (r.front == Front::Cli ? "drop " + opt("error_estimate") : opt("error_estimate") + "=False is not allowed"));
  } else if (r.time_budget > 0) {
    throw UsageError(opt("time_budget") + " applies to " + opt("target_error") + " only");
  }
}

ModesStudy articleModes(ArticleScene scene, const ModesRequest& r) {
  std::optional<SegmentsChoice> choice;
  if (r.target_error > 0) {
    choice = segmentsForTarget(scene, r.modes, r.target_error, kMaxTargetSegments, r.time_budget);
    overrideSegments(scene, choice->segments);
  }
  ModesOptions opt;
  opt.max_modes = r.modes;
  opt.with_shapes = true;  // the JSON on stdout and in --out is one object: shapes in both
  opt.points = checkedPoints(r.points, scene.article, declaredName<ModesParams>("points", r.front));
  for (const std::string& text : r.strains) {
    const std::string what = declaredName<ModesParams>("strains", r.front) + " " + text;
    const auto p = split(text, ':');
    const std::optional<bool> out = p.size() == 3 ? strainBendsOutOfPlane(p[2]) : std::optional<bool>(false);
    if (p.size() < 2 || p.size() > 3 || !out)
      throw UsageError(what + ": expected A:B[:in|out], two stations of one link and the bending read (in the plane, the "
                              "default, or out of it), e.g. link3a@0.1m:link3a@0.5m");
    std::string why;
    const std::optional<StrainSpan> span = strainSpan(scene.article, p[0], p[1], why, *out);
    if (!span) throw UsageError(what + ": " + why);
    opt.strains.push_back({text, p[0], p[1], span->surface_m, span->x_b - span->x_a, *out});
  }
  opt.damping = scene.damping;
  ModesReport rep = runModes(scene, opt);
  if (r.error_estimate) rep.discretization = estimateDiscretization(scene, rep);
  rep.segments_choice = choice;
  for (const auto& w : plausibilityWarnings(scene, rep)) rep.warnings.push_back("likely a unit mistake: " + w);
  ModesStudy s;
  s.json = modesToJson(rep);
  s.text = formatModesText(rep);
  s.csv = modesCsv(rep);
  s.vtp = modesVtp(rep, scene.article);
  s.report = std::move(rep);
  return s;
}

}  // namespace

ModesStudy runModesStudy(const Scene& scene, const ModesRequest& r) {
  const auto* article = std::get_if<ArticleScene>(&scene);
  checkRequest(r, article != nullptr);
  ModesStudy s;
  if (article) {
    s = articleModes(*article, r);
  } else {
    const auto& h = std::get<HamsasScene>(scene);
    if (!r.points.empty()) throw UsageError(declaredName<ModesParams>("points", r.front) + " applies to the article's scenes");
    if (!r.strains.empty()) throw UsageError(declaredName<ModesParams>("strains", r.front) + " applies to the article's scenes");
    const HamsasModes m = analyseHamsas(h.isolator);
    s.json = hamsasModesJson(h, m, r.modes);
    s.text = hamsasModesText(h, m, r.modes);
    s.csv = hamsasModesCsv(m, r.modes);
    s.vtp = hamsasModesVtp(h, m, r.modes);
  }
  checkResultFinite(s.json);  // before any file is committed or any result returned
  checkResultFinite(s.text);
  return s;
}

}  // namespace mmv::app

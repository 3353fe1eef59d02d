#include "sim/app/plan_studies.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_placement.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/io/placement_geometry.hpp"
#include "sim/io/tam_report.hpp"
#include "sim/modes/sensor_placement.hpp"

namespace mmv::app {

CheckStudy runCheckStudy(const Scene& scene, const CheckRequest& r) {
  checkRange(r.front, "--margin", r.margin_pct, 0, 99);
  if (!(r.band_min_hz >= 0) || !(r.band_max_hz > r.band_min_hz) || !std::isfinite(r.band_max_hz))
    throw UsageError(strf("%s: expected 0 <= F_MIN_HZ < F_MAX_HZ (got %g:%g)", optionName(r.front, "--band").c_str(),
                          r.band_min_hz, r.band_max_hz));
  const ArticleScene& article = articleOf(scene, "check");
  CheckOptions opt;
  opt.required_margin_pct = r.margin_pct;
  opt.band_min_hz = r.band_min_hz;
  opt.band_max_hz = r.band_max_hz;
  CheckStudy s{runCheck(article, opt), {}, {}, {}};
  s.json = checkJson(s.report);
  s.text = checkText(s.report);
  s.markdown = checkMarkdown(s.report);
  checkResultFinite(s.json);
  return s;
}

PlacementStudyResult runPlacementStudy(const Scene& scene, const PlacementRequest& r) {
  const auto opt = [&](const char* flag) { return optionName(r.front, flag); };
  PlacementOptions o;
  if (!r.modes.empty() && r.below_given)
    throw UsageError(opt("--below-hz") + " and " + opt("--modes") + " both choose the target modes: give one");
  for (int m : r.modes)
    if (m < 1 || m > 100000) throw UsageError(strf("%s: mode numbers start at 1 (got %d)", opt("--modes").c_str(), m));
  checkRange(r.front, "--below-hz", r.below_hz, 0, kUnbounded, /*open_low=*/true);
  checkRange(r.front, "--spacing", r.spacing_m, 1e-3, 100);
  checkRange(r.front, "--count", r.count, 1, 100000);
  if (!parsePlacementMethod(r.method, o.method))
    throw UsageError(opt("--method") + ": unknown method '" + r.method + "' (known: efi, mke, dpr)");
  o.modes = modeNumbers(r.modes);  // the front end's numbers, checked above
  o.below_hz = r.below_hz;
  o.spacing_m = r.spacing_m;
  o.triaxial = r.triaxial;
  o.count = r.count;
  for (const auto& name : r.tam) {
    if (name == "all") {
      o.tam = {TamMethod::Guyan, TamMethod::Irs, TamMethod::Serep};
      continue;
    }
    TamMethod m;
    if (!parseTamMethod(name, m))
      throw UsageError(opt("--tam") + ": unknown test-analysis model '" + name + "' (known: guyan, irs, serep, all)");
    if (std::find(o.tam.begin(), o.tam.end(), m) == o.tam.end()) o.tam.push_back(m);
  }
  if (!o.tam.empty() && !std::holds_alternative<ArticleScene>(scene))
    throw UsageError(opt("--tam") + " applies to the article's scenes (the isolator's TAM is not built yet)");
  checkRange(r.front, "--sensor-mass", r.sensor_mass_kg, 0, 100);
  o.sensor_mass_kg = r.sensor_mass_kg;
  if (o.sensor_mass_kg > 0 && !std::holds_alternative<ArticleScene>(scene))
    throw UsageError(opt("--sensor-mass") + " applies to the article's scenes (the isolator's loading is not built yet)");
  PlacementStudyResult s;
  if (const auto* article = std::get_if<ArticleScene>(&scene)) {
    s.study = runPlacement(*article, o);
  } else {
    const auto& isolator = std::get<HamsasScene>(scene);
    s.isolator_modes = analyseHamsas(isolator.isolator);
    s.study = runHamsasPlacement(isolator, *s.isolator_modes, o);
  }
  s.json = placementJson(s.study);
  s.text = placementText(s.study);
  if (!s.study.tams.empty()) s.tam_csv = tamCsv(s.study);
  if (const auto* article = std::get_if<ArticleScene>(&scene)) {  // the isolator's test geometry: not yet
    s.channels_csv = placementChannelsCsv(s.study);
    uff::File geometry = placementGeometry(s.study, article->name);
    uff::stampNow(geometry);
    s.geometry_uff = uff::write(geometry);
  }
  checkResultFinite(s.json);  // before any file is committed
  return s;
}

}  // namespace mmv::app

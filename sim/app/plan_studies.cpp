#include "sim/app/plan_studies.hpp"

#include <algorithm>
#include <cmath>

#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_placement.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/exciter_report.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/io/placement_geometry.hpp"
#include "sim/io/vtk_export.hpp"
#include "sim/io/tam_report.hpp"
#include "sim/modes/sensor_placement.hpp"

namespace mmv::app {

CheckStudy runCheckStudy(const Scene& scene, const CheckRequest& r) {
  checkOptions<CheckParams>(r, r.front);
  const ArticleScene& article = articleOf(scene, "check");
  CheckOptions opt;
  opt.required_margin_pct = r.margin;
  opt.band_min_hz = r.band.min_hz;
  opt.band_max_hz = r.band.max_hz;
  CheckStudy s{runCheck(article, opt), {}, {}, {}};
  s.json = checkJson(s.report);
  s.text = checkText(s.report);
  s.markdown = checkMarkdown(s.report);
  checkResultFinite(s.json);
  return s;
}

namespace {

/// --keep-out LINK:FROM:TO, each checked against the article: a link it has, 0 <= FROM <
/// TO <= its length, not all of it.
std::vector<PlacementOptions::KeepOut> keepOuts(const Scene& scene, const PlacementRequest& r) {
  const std::string flag = optionName(r.front, "--keep-out");
  std::vector<PlacementOptions::KeepOut> out;
  if (r.keep_out.empty()) return out;
  const auto* article = std::get_if<ArticleScene>(&scene);
  if (!article) throw UsageError(flag + " applies to the article's scenes (its links)");
  for (const auto& text : r.keep_out) {
    const auto a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
    const std::optional<double> from = b == std::string::npos ? std::nullopt : finiteNumber(text.substr(a + 1, b - a - 1));
    const std::optional<double> to = b == std::string::npos ? std::nullopt : finiteNumber(text.substr(b + 1));
    if (!from || !to) throw UsageError(flag + " " + text + ": expected LINK:FROM_M:TO_M, e.g. link1:2.3:2.44");
    const std::string link = text.substr(0, a);
    std::vector<std::string> names;
    for (const auto& l : article->article.links) names.push_back(l.name);
    const auto it = std::find(names.begin(), names.end(), link);
    if (it == names.end()) throw UsageError(flag + " " + text + ": no link '" + link + "'" + didYouMean(link, names));
    const double length = article->article.links[static_cast<std::size_t>(it - names.begin())].length;
    if (!(*from >= 0 && *from < *to && *to <= length))
      throw UsageError(strf("%s %s: expected 0 <= FROM < TO <= %g m (the link's length)", flag.c_str(), text.c_str(), length));
    if (*from <= 0 && *to >= length)
      throw UsageError(flag + " " + text + ": covers the whole link, so no sensor could see it; narrow it to the stretch to avoid");
    out.push_back({link, *from, *to});
  }
  return out;
}

}  // namespace

namespace {

/// The instrument placed (`--instrument`, from the scene's catalogue) into `o`: its mass
/// per housing (three uniaxial ones make a --triaxial block), triaxial when it is a block.
void placedInstrument(const ArticleScene& scene, const PlacementRequest& r, PlacementOptions& o) {
  const auto opt = [&](const char* name) { return optionName(r.front, name); };
  const std::string name = r.instrument.empty() ? "accelerometer" : r.instrument;
  const InstrumentSpec* i = findInstrument(scene, name);
  if (!i) {
    std::vector<std::string> names;
    std::string list;
    for (const InstrumentSpec& k : scene.instruments) names.push_back(k.name), list += (list.empty() ? "" : ", ") + k.name;
    throw UsageError(opt("--instrument") + ": unknown instrument '" + name + "'" + didYouMean(name, names) + " (the scene's: " + list + ")");
  }
  if (i->spec.kind != "accelerometer")
    throw UsageError(opt("--instrument") + " " + name + ": " + (i->spec.kind == "encoder" ? "an encoder" : "a rate gyro") + "; sensors are placed as accelerometers");
  o.instrument = *i;
  if (i->axes == 3) o.triaxial = true;
  if (!r.instrument.empty() && r.sensor_mass_kg > 0)
    throw UsageError(opt("--sensor-mass") + " and " + opt("--instrument") + " both give the sensors' mass: give one (the instrument's is " +
                     strf("%g kg", i->mass_kg) + ")");
  if (r.sensor_mass_kg == 0) o.sensor_mass_kg = i->mass_kg * (o.triaxial && i->axes == 1 ? 3 : 1);
  o.iterate_loaded = r.iterate_loaded;
  if (r.iterate_loaded && o.sensor_mass_kg == 0)
    throw UsageError(opt("--iterate-loaded") + ": the " + name + " is massless: nothing loads the model (give --sensor-mass, or the "
                     "instrument's mass_kg in the scene's instruments:)");
}

}  // namespace

namespace {

/// The article's test geometry (channels, nodes, the ParaView set) and, on a scene with
/// a shaker, its attachment and levels on the chosen sensors; on the base table, the
/// table's own levels.
void addTestGeometry(const ArticleScene& article, double max_deflection_m, PlacementStudyResult& s) {
  s.channels_csv = placementChannelsCsv(s.study);
  s.sensors_vtp = placementVtp(s.study);
  if (s.study.strain) {  // strain readings: no motion at nodes, no accelerometer levels
    const bool levels = article.shaker || article.article.base.type == BaseType::Table;
    s.text += std::string("\nStrain sensors: channels.csv lists them (quantity strain, m/m); no test_geometry.uff (its records "
                          "hold motions at nodes)") +
              (levels ? "; the shaker's and the table's levels are planned on accelerometers (place those to see them)" : "") + "\n";
    return;
  }
  uff::File geometry = placementGeometry(s.study, article.name);
  uff::stampNow(geometry);
  s.geometry_uff = uff::write(geometry);
  if (article.shaker) {
    s.exciter = runExciter(article, s.study, max_deflection_m);
    s.json["exciter"] = exciterJson(*s.exciter);
    s.text += exciterText(*s.exciter);
    s.exciter_csv = exciterCsv(*s.exciter);
    s.exciter_ranking_csv = exciterRankingCsv(*s.exciter);
  }
  if (article.article.base.type == BaseType::Table && !s.study.target_modes.empty()) {
    s.table_levels = runTableLevels(article, s.study, max_deflection_m);
    s.json["table_levels"] = tableLevelsJson(*s.table_levels);
    s.text += tableLevelsText(*s.table_levels);
  }
}

}  // namespace

namespace {

/// PlacementStudyResult::summary_lines, from the study's own numbers.
std::vector<std::string> summaryLines(const PlacementStudyResult& s) {
  const PlacementStudy& p = s.study;
  std::vector<std::string> out;
  const auto& f = p.target_frequencies_hz;
  out.push_back(strf("Target modes: %zu, %.4g-%.4g Hz", f.size(), f.empty() ? 0.0 : f.front(), f.empty() ? 0.0 : f.back()));
  out.push_back(strf("Sensors: %zu %s by %s, of %zu candidates", p.result.kept_blocks.size(),
                     p.strain ? strf("strain films of %g m", p.strain_span_m).c_str() : p.triaxial ? "triaxial blocks" : "uniaxial",
                     p.method.c_str(), p.candidates.size()));
  if (p.requested > static_cast<int>(p.result.kept_blocks.size()))
    out.push_back(strf("warning: %zu of the %d asked for (the separation)", p.result.kept_blocks.size(), p.requested));
  const auto alike = indistinguishableModes(p);
  std::string pairs;
  for (const auto& [a, b] : alike) pairs += strf(" %d&%d", a, b);
  out.push_back(strf("Fisher information: condition %s; largest off-diagonal AutoMAC %.3f",
                     std::isfinite(p.result.fisher_condition) ? strf("%.3g", p.result.fisher_condition).c_str() : "singular",
                     p.result.max_offdiagonal_mac));
  out.push_back(alike.empty() ? std::string("Every pair of target modes told apart (AutoMAC <= 0.9)")
                              : "warning: modes alike (AutoMAC > 0.9):" + pairs);
  for (const TamResult& t : p.tams) {
    int fail = 0;
    double worst = 0;
    for (const auto& m : t.modes) {
      fail += !m.pass;
      if (std::abs(m.frequency_error) >= std::abs(worst)) worst = m.frequency_error;
    }
    out.push_back(strf("TAM %s: %zu of %zu targets pass%s; worst frequency error %+.3g %%", tamMethodName(t.method), t.modes.size() - fail,
                       t.modes.size(), t.pass ? "" : " (FAIL)", 100 * worst));
  }
  if (p.loading) {
    const SensorLoading& l = *p.loading;
    double worst = 0;
    int mode = 0, heavy = 0;
    for (const auto& m : l.modes) {
      heavy += m.beyond_first_order || m.lost;
      if (std::abs(m.shift) >= std::abs(worst)) worst = m.shift, mode = m.mode.number();
    }
    out.push_back(strf("%ssensors' mass %.3g kg each (%.3g kg): mode %d shifts %+.2f %%; %d beyond first order",
                       heavy ? "warning: " : "", l.sensor_mass_kg, l.added_kg, mode, 100 * worst, heavy));
    if (!l.iterations.empty()) {
      const LoadedIteration& last = l.iterations.back();
      out.push_back(last.settled ? strf("Placed on the model carrying them: settled after %zu pass%s%s", l.iterations.size(), l.iterations.size() == 1 ? "" : "es",
                                        last.tie ? " (a tie)" : "")
                                 : strf("warning: placed on the model carrying them: %s after %zu passes, the last kept",
                                        last.repeats ? "the passes cycle" : "unsettled", l.iterations.size()));
    }
  }
  if (s.exciter) {
    int seen = 0;
    for (const auto& m : s.exciter->modes) seen += m.seen;
    out.push_back(strf("Shaker at %s %s: %d of %zu targets seen at >= 20 dB under a sine dwell", s.exciter->at.c_str(),
                       s.exciter->axis.c_str(), seen, s.exciter->modes.size()));
  }
  if (s.table_levels) {
    int seen = 0, above = 0;
    for (const auto& m : s.table_levels->modes) seen += m.seen, above += !m.within_bandwidth;
    out.push_back(strf("Base table: %d of %zu targets seen at >= 20 dB (%d above its bandwidth)", seen, s.table_levels->modes.size(), above));
  }
  return out;
}

/// --strain-span: strain gauges or films in place of accelerometers, checked against
/// everything else the request asks (each combination they cannot meet named).
void strainOptions(const Scene& scene, const PlacementRequest& r, PlacementOptions& o) {
  const auto opt = [&](const char* flag) { return optionName(r.front, flag); };
  const std::string flag = opt("--strain-span");
  checkRange(r.front, "--strain-span", r.strain_span_m, 1e-3, 100);
  const auto* article = std::get_if<ArticleScene>(&scene);
  if (!article) throw UsageError(flag + " applies to the article's scenes (the isolator's bodies are rigid: nothing bends)");
  const auto refuse = [&](bool given, const char* other, const std::string& why) {
    if (given) throw UsageError(flag + " and " + opt(other) + ": " + why);
  };
  refuse(o.method != PlacementMethod::EffectiveIndependence, "--method",
         "strain sensors are placed by effective independence only (kinetic energy and driving-point residue rank motions)");
  refuse(r.triaxial, "--triaxial", "a strain gauge or film reads one strain: place them uniaxial");
  refuse(r.sensor_mass_kg > 0 || r.iterate_loaded || !r.instrument.empty(),
         r.sensor_mass_kg > 0 ? "--sensor-mass" : r.iterate_loaded ? "--iterate-loaded" : "--instrument",
         "strain sensors are placed massless (foil or film on the surface)");
  refuse(r.keep_scene_sensors, "--keep-scene-sensors", "the scene's accelerometers are kept in an accelerometer placement");
  o.strain_span_m = r.strain_span_m;
  o.instrument = *findInstrument(*article, "strain");
}

}  // namespace

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
  checkRange(r.front, "--sensor-mass", r.sensor_mass_kg, 0, 100);
  checkRange(r.front, "--min-separation", r.min_separation_m, 0, 100);
  if (r.max_deflection_m != 0) checkRange(r.front, "--max-deflection", r.max_deflection_m, 1e-6, 100);
  o.min_separation_m = r.min_separation_m;
  if (r.channels != 0) {
    checkRange(r.front, "--channels", r.channels, 1, 300000);
    o.count = r.triaxial ? r.channels / 3 : r.channels;
    if (o.count < 1)
      throw UsageError(strf("%s %d: a triaxial block takes 3 channels", opt("--channels").c_str(), r.channels));
  }
  o.keep_out = keepOuts(scene, r);
  o.keep_scene_sensors = r.keep_scene_sensors;
  if (r.keep_scene_sensors && !std::holds_alternative<ArticleScene>(scene))
    throw UsageError(opt("--keep-scene-sensors") + " applies to the article's scenes (the isolator's sensors are not scene data)");
  o.sensor_mass_kg = r.sensor_mass_kg;
  if (r.strain_span_m != 0) {
    strainOptions(scene, r, o);
  } else if (const auto* article = std::get_if<ArticleScene>(&scene)) {
    placedInstrument(*article, r, o);
  } else {
    if (!r.instrument.empty())
      throw UsageError(opt("--instrument") + " applies to the article's scenes (the isolator's sensors are not scene data)");
    o.iterate_loaded = r.iterate_loaded;
    if (r.iterate_loaded && o.sensor_mass_kg == 0)
      throw UsageError(opt("--iterate-loaded") + ": the sensors are massless: nothing loads the isolator (give " + opt("--sensor-mass") + ")");
  }
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
  if (!s.study.tams.empty()) s.tam_csv = tamCsv(s.study), s.tam_mat = tamMat(s.study);
  if (const auto* article = std::get_if<ArticleScene>(&scene)) {
    addTestGeometry(*article, r.max_deflection_m, s);
  } else {  // the isolator's channels and nodes (its ParaView set is modes.vtp's boxes)
    s.channels_csv = placementChannelsCsv(s.study);
    uff::File geometry = placementGeometry(s.study, std::get<HamsasScene>(scene).name);
    uff::stampNow(geometry);
    s.geometry_uff = uff::write(geometry);
  }
  s.summary_lines = summaryLines(s);
  checkResultFinite(s.json);  // before any file is committed
  return s;
}

}  // namespace mmv::app

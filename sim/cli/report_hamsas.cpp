// mmvlab report on a HAM-SAS scene: the isolator's renders, its modes against the
// measured features, the sensor plan, the ground-to-optical-table transmissibility
// against the 70-80 dB goal, the scene; report.json beside the page holds the studies'
// JSON documents (modes, place-sensors and frf --json of the same scene).
#include <filesystem>
#include <variant>

#include "sim/app/hamsas_linear_study.hpp"
#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/cli/figures.hpp"
#include "sim/cli/report_common.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/report.hpp"
#include "sim/io/review_report.hpp"
#include "sim/view/hamsas_drawing.hpp"

namespace mmv::cli {
namespace {

using namespace report;

/// The sensor plan's band and count: the report's when given; else the isolator's
/// modes below 5 Hz (the article's 0.1-50 Hz holds dozens of them) and 12 sensors.
std::pair<double, int> isolatorPlan(const ReportArgs& a) {
  return {a.given.count("--band") ? parseBand(a.band).second : 5.0, a.given.count("--sensors") ? a.sensors : 12};
}

html::Section isolatorSection(const ReportArgs& a, const HamsasScene& scene, const HamsasModes& h, Embedder& em) {
  html::Section s{"isolator", "The isolator", "", {}, {}};
  addViewFigures(s, a, em, {"front", "iso"}, "isolator", [&](const std::string& view) {
    DrawList d = drawHamsas(scene, h);
    d.title += "  (" + view + " view)";
    return d;
  }, "The isolator's bodies at the design configuration (%s view), with its springs, joints and sensors.");
  s.accuracy.push_back("Each body is drawn as the uniform box of its mass and principal moments of inertia, at its mass centre.");
  return s;
}

std::string isolatorTiles(const Json& modes, const Json& placement, const Json& frf) {
  int shown = 0, features = 0;
  double worst = 0;
  for (const auto& f : modes.at("features")) {
    ++features;
    if (!f.at("model_hz").is_number()) continue;
    ++shown;
    worst = std::max(worst, std::abs(f.at("model_hz").get<double>() / f.at("measured_hz").get<double>() - 1));
  }
  const double x10 = frf.at("at_10_hz_db").at(0).at(0).get<double>();
  return "<div class=\"summary\">" + tile("na", "check: n/a", "its lines are the MMV facility's; the isolator's goal is below") +
         tile(shown == features ? "pass" : "warn", strf("%d of %d measured features", shown, features),
              strf("shown by a mode, largest error %.2g %%", 100 * worst)) +
         tile(placement.at("indistinguishable_mode_pairs").empty() ? "pass" : "warn",
              strf("%zu sensors", placement.at("chosen").size()),
              "max off-diagonal AutoMAC " + reportNumber(placement.at("max_offdiagonal_automac"))) +
         tile(x10 <= -70 ? "pass" : "fail", strf("x at 10 Hz: %.1f dB", x10), "the goal: 70-80 dB of attenuation above 10 Hz") +
         "</div>";
}

html::Page isolatorPage(const ReportArgs& args, const HamsasScene& scene, const app::ModesStudy& modes,
                        const app::PlacementStudyResult& placement, const app::HamsasFrfStudy& frf, Embedder& em) {
  const Scene loaded = scene;
  const auto [below_hz, count] = isolatorPlan(args);
  const HamsasModes h = analyseHamsas(scene.isolator);
  html::Page page;
  page.title = "Test-readiness report: " + scene.name;
  page.subtitle = (args.scene_path.empty() ? std::string("HAM-SAS scene") : args.scene_path) + " \u2014 " +
                  strf("HAM-SAS isolator, %zu bodies, %d coordinates", h.model.bodies.size(), modes.json.value("coordinates", 0)) +
                  " \u2014 mmvlab " + mmvlabVersion();
  page.summary = isolatorTiles(modes.json, placement.json, frf.json);
  page.sections.push_back(isolatorSection(args, scene, h, em));
  const int sheet = std::min<int>(6, static_cast<int>(h.modes.size()));
  page.sections.push_back({"modes", "Modes against the measured features",
                           html::table(hamsasFeatureTable(modes.json)) + html::table(hamsasModeTable(modes.json)) +
                               (sheet > 0 ? modesSheetFigure(em, "iso", sheet, [&](int m) { return drawHamsas(scene, h, ModeNumber(m), 1.0, 0, true); },
                                                             "the design configuration")
                                          : ""),
                           hamsasModesAccuracy(modes.json),
                           {commandFor(args, "modes", strf("--modes %d --out modes", args.modes)),
                            commandFor(args, "render", strf("--mode 1-%d --view iso --out modes.png", sheet))}});
  const std::string sensors = em.figures([&](const FigurePath& at) { writePlacementFigures(at, loaded, placement); },
                                         [](const std::string& name) {
                                           if (name == "automac.png") return std::string("AutoMAC of the target modes seen by the chosen sensors (0: told apart, 1: alike).");
                                           return std::string("The chosen sensors on the isolator.");
                                         });
  page.sections.push_back({"sensors", "Sensor plan",
                           html::table(sensorTable(placement.json)) + "<div class=\"grid\">" + sensors + "</div>",
                           placementAccuracy(placement.json),
                           {commandFor(args, "place-sensors", strf("--below-hz %s --count %d --out sensors", shortest(below_hz).c_str(), count))}});
  const std::string curves = em.figures(
      [&](const FigurePath& at) { writeTransmissibilityPlots(at, scene.name, frf.f, frf.T, frf.T10, "", {}, ""); },
      [](const std::string& name) { return "Ground-to-optical-table transmissibility: " + name.substr(17, name.size() - 21) + "."; });
  page.sections.push_back({"frf", "Transmissibility against the 70-80 dB goal",
                           html::table(transmissibilityTable(frf.json)) + "<div class=\"grid\">" + curves + "</div>",
                           transmissibilityAccuracy(frf.json), {commandFor(args, "frf", "--out frf")}});
  page.sections.push_back(sceneSection(args, scene.text));
  page.footer = "Made by " + commandFor(args, "report", "--out " + shellWord(args.out)) +
                ". Every table is the JSON of the command under it (report.json holds them); the figures are those "
                "commands' figures. check has no HAM-SAS lines: its requirements are the MMV facility's.";
  return page;
}

}  // namespace

int runHamsasReport(const ReportArgs& args, const HamsasScene& scene, OutputDir& out) {
  const Scene loaded = scene;
  const auto [below_hz, count] = isolatorPlan(args);
  app::ModesStudy modes;
  app::PlacementStudyResult placement;
  {
    const ProgressStage stage("report: modes");
    app::ModesRequest r;
    r.modes = args.modes;
    modes = app::runModesStudy(loaded, r);
  }
  {
    const ProgressStage stage("report: sensor plan");
    app::PlacementRequest r;
    r.below_hz = below_hz;
    r.below_given = true;
    r.count = count;
    try {
      placement = app::runPlacementStudy(loaded, r);
    } catch (const UsageError& e) {  // it names place-sensors' options (--count is --sensors here)
      throw UsageError(strf("the sensor plan (report --sensors %d, modes below %g Hz): ", count, below_hz) + e.what());
    }
  }
  app::HamsasFrfStudy frf;
  {
    const ProgressStage stage("report: transmissibility");
    frf = app::runHamsasFrfStudy(scene, app::LinearRequest{});
  }
  const ProgressStage stage("report: figures and page");
  Embedder em(out);
  const html::Page page = isolatorPage(args, scene, modes, placement, frf, em);
  Json doc;
  doc["mmvlab_version"] = mmvlabVersion();
  doc["command"] = "report";
  doc["scene"] = {{"name", scene.name}, {"source", args.scene_path}};
  doc["figures"] = em.count();
  doc["modes"] = modes.json;
  doc["placement"] = placement.json;
  doc["frf"] = frf.json;
  const std::string where = writeReport(out, args.out, page, doc);
  emitResult(strf("report: %s\n  %zu modes tabulated, %zu measured features, %zu sensors, transmissibility x at 10 Hz %.1f dB, "
                  "%d figures\n",
                  scene.name.c_str(), modes.json.at("modes").size(), modes.json.at("features").size(),
                  placement.json.at("chosen").size(), frf.json.at("at_10_hz_db").at(0).at(0).get<double>(), em.count()) +
             where);
  return kOk;
}

}  // namespace mmv::cli

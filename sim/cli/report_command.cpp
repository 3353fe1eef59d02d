// mmvlab report: the test-readiness review's page. One self-contained HTML file
// (sim/io/html_page.hpp) with the article and facility renders, check's verdicts, the
// mode table, the sensor plan, the frequency responses, each part's accuracy statement
// and the command that reproduces it, and the scene; report.json beside it holds the
// studies' JSON documents the page was made from.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <variant>

#include "sim/app/linear_study.hpp"
#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/report_common.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/files.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/html_page.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/report.hpp"
#include "sim/io/review_report.hpp"
#include "sim/view/article_drawing.hpp"

namespace mmv::cli {
namespace report {

/// A word of a shell command line, quoted when the shell would split or expand it.
std::string shellWord(const std::string& w) {
  if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./:=,@+") ==
                        std::string::npos)
    return w;
  std::string q = "'";
  for (const char c : w) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// "mmvlab VERB [SCENE] [scene options] EXTRA": the command that reproduces a part.
std::string commandFor(const ReportArgs& a, const std::string& verb, const std::string& extra) {
  std::string c = "mmvlab " + verb;
  if (!a.scene_path.empty()) c += " " + shellWord(a.scene_path);
  if (a.segments) c += " --segments " + std::to_string(*a.segments);
  if (a.no_gravity) c += " --no-gravity";
  for (const auto& s : a.sets) c += " --set " + shellWord(s);
  return extra.empty() ? c : c + " " + extra;
}

std::string tile(const std::string& cls, const std::string& big, const std::string& small) {
  return "<div class=\"tile " + cls + "\"><b>" + html::escape(big) + "</b>" + html::escape(small) + "</div>";
}

/// The scene as read (the file's text, or the embedded default's) and the overrides the
/// report ran with.
html::Section sceneSection(const ReportArgs& a, const std::string& text) {
  html::Section s{"scene", "The scene", "", {}, {}};
  std::string changes;
  if (a.segments) changes += "--segments " + std::to_string(*a.segments) + "; ";
  if (a.no_gravity) changes += "--no-gravity; ";
  for (const auto& set : a.sets) changes += "--set " + set + "; ";
  s.body = "<p>" + html::escape(a.scene_path.empty() ? std::string("The embedded default scene (mmvlab scene prints it).")
                                                      : "The scene file " + a.scene_path + ".") +
           (changes.empty() ? "" : " Run with " + html::escape(changes.substr(0, changes.size() - 2)) +
                                       " on top of it (every number above includes them).") +
           "</p>\n<pre>" + html::escape(text) + "</pre>";
  s.commands.push_back(a.scene_path.empty() ? "mmvlab scene > scene.yaml" : "cat " + shellWord(a.scene_path));
  return s;
}

void addViewFigures(html::Section& s, const ReportArgs& a, Embedder& em, const std::vector<std::string>& views,
                    const std::string& prefix, const std::function<DrawList(const std::string& view)>& draw,
                    const std::string& caption) {
  s.body += "<div class=\"grid\">";
  for (const std::string& view : views) {
    const DrawList d = draw(view);
    Camera camera;
    presetCamera(view, d.bounds(), camera, d.up);
    const std::string file = prefix + "_" + view + ".png";
    s.body += em.figure(file, [&](const std::string& p) { figures::framePng(p, d, camera, {1280, 720, 3}); },
                        "the " + prefix + ", " + view + " view", strf(caption.c_str(), view.c_str()));
    s.commands.push_back(commandFor(a, "render", "--view " + view + " --out " + file));
  }
  s.body += "</div>";
}

std::string modesSheetFigure(Embedder& em, const std::string& view, int n, const std::function<DrawList(int mode)>& tile,
                             const std::string& about) {
  std::vector<DrawList> tiles;
  std::vector<Camera> cameras;
  for (int m = 1; m <= n; ++m) {
    tiles.push_back(tile(m));
    Camera c;
    presetCamera(view, tiles.back().bounds(), c, tiles.back().up);
    cameras.push_back(c);
  }
  return em.figure("modes.png", [&](const std::string& p) { figures::contactSheetPng(p, tiles, cameras, {480, 320, 2}, 3); },
                   "the first modes", strf("Modes 1 to %d about ", n) + about +
                                          ", each drawn at an amplitude that shows it (a mode shape has no physical size).");
}

std::string writeReport(OutputDir& out, const std::string& dir, const html::Page& page, const Json& doc) {
  checkResultFinite(doc);
  const std::string page_html = html::page(page);
  out.write("report.html", page_html);
  out.write("report.json", doc.dump(2) + "\n");
  const std::string where = strf("  page: %s (%.1f MB)\n", (std::filesystem::path(dir) / "report.html").c_str(), page_html.size() / 1e6);
  out.commit();
  return where;
}

}  // namespace report

namespace {

using namespace report;

html::Section articleSection(const ReportArgs& a, const ArticleScene& scene, const SolvedScene& solved, Embedder& em) {
  SimTK::State st = solved.equilibrium.state;
  solved.model->getSystem().realize(st, SimTK::Stage::Position);
  const bool spatial = scene.article.model == ArticleModel::Spatial;
  html::Section s{"article", "The article and the facility", "", {}, {}};
  addViewFigures(s, a, em, {spatial ? "side" : "front", "iso"}, "article", [&](const std::string& view) {
    DrawList d = drawArticle(scene, *solved.model, st);
    d.title += "  (static equilibrium, " + view + " view)";
    return d;
  }, "The article held at its static equilibrium (%s view), with the facility and the scene's sensors.");
  s.accuracy.push_back("Drawn at the equilibrium the mode table is computed about; deflections to scale.");
  return s;
}

std::string modesSheet(const ArticleScene& scene, const SolvedScene& solved, int n, Embedder& em) {
  return modesSheetFigure(em, scene.article.model == ArticleModel::Spatial ? "iso" : "front", n,
                          [&](int m) { return ModeFrames(scene, solved, ModeNumber(m), 0.0).frame(1.0, true); }, "the equilibrium");
}

/// The frequency responses' accuracy at a glance: the reduced model against its target,
/// and the mesh's share near the peaks (warned above 10 % of a peak).
std::string frfTiles(const Json& frf) {
  const Json& need = frf.value("modes_for_target", Json());
  const double error = frf.value("max_relative_frf_error", 0.0), target = need.value("target", 0.01);
  const int kept = static_cast<int>(frf.at("kept_frequencies_hz").size());
  std::string out = tile(error <= target ? "pass" : "warn", strf("%d-mode reduced model", kept),
                         strf("%.3g %% of each peak (target %.3g %%", 100 * error, 100 * target) +
                             (need.value("reached", false) ? strf("; %d modes meet it)", need.value("modes", 0)) : std::string(")")));
  const Json& mesh = frf.value("mesh_frf_error_estimate", Json());
  if (mesh.is_number())
    out += tile(mesh.get<double>() <= 0.1 ? "pass" : "warn", strf("mesh: %.3g %% of a peak", 100 * mesh.get<double>()),
                "the FRF's mesh error near mode " + frf.at("mesh_frf_error_mode").dump());
  return out;
}

/// The verdicts at a glance: a tile per part.
std::string summaryTiles(const Json& check, const Json& modes, const Json& placement, const Json& frf) {
  const std::string overall = check.at("overall").get<std::string>();
  std::string in_band = "modes in band: not checked";
  for (const auto& l : check.at("lines"))
    if (l.at("id") == "modes.in_band" && l.at("demand").is_number())
      in_band = strf("%d ", l.at("demand").get<int>()) + l.at("requirement").get<std::string>();
  std::map<std::string, int> verdicts;  // by kind, in the order the page lists them
  for (const auto& l : check.at("lines")) ++verdicts[verdictClass(l.at("verdict").get<std::string>())];
  std::string counts;
  for (const char* v : {"fail", "warn", "pass", "advisory", "info", "na"})
    if (verdicts[v] > 0) counts += (counts.empty() ? "" : ", ") + strf("%d %s", verdicts[v], v == std::string("na") ? "n/a" : v);
  const Json& first = modes.at("modes").empty() ? Json() : modes.at("modes").front();
  return "<div class=\"summary\">" +
         tile(verdictClass(overall), "check: " + overall, counts) +
         tile("", in_band, "first at " + reportNumber(first.value("frequency_hz", Json())) + " Hz") +
         tile(placement.at("indistinguishable_mode_pairs").empty() ? "pass" : "warn",
              strf("%zu sensors", placement.at("chosen").size()), "max off-diagonal AutoMAC " +
                                                                      reportNumber(placement.at("max_offdiagonal_automac"))) +
         frfTiles(frf) + "</div>";
}

struct Parts {
  app::CheckStudy check;
  app::ModesStudy modes;
  app::PlacementStudyResult placement;
  std::optional<app::LinearStudy> frf;
};

Parts runParts(const ReportArgs& a, const Scene& loaded) {
  Parts p;
  {
    const ProgressStage stage("report: check");
    app::CheckRequest r;
    const auto [lo, hi] = parseBand(a.band);
    r.band = {lo, hi};
    p.check = app::runCheckStudy(loaded, r);
  }
  {
    const ProgressStage stage("report: modes");
    app::ModesRequest r;
    r.modes = a.modes;
    r.segments_given = a.segments.has_value();
    p.modes = app::runModesStudy(loaded, r);
  }
  {
    const ProgressStage stage("report: sensor plan");
    app::PlacementRequest r;
    r.below_hz = parseBand(a.band).second;
    r.below_given = true;
    r.count = a.sensors;
    try {
      p.placement = app::runPlacementStudy(loaded, r);
    } catch (const UsageError& e) {  // it names place-sensors' options (--count is --sensors here)
      throw UsageError(std::string("the sensor plan (report --sensors ") + std::to_string(a.sensors) + "): " + e.what());
    }
  }
  const ProgressStage stage("report: frequency responses");
  app::LinearRequest r;
  r.segments_given = a.segments.has_value();
  p.frf.emplace(app::runLinearStudy(std::get<ArticleScene>(loaded), r));
  return p;
}

std::vector<html::Section> studySections(const ReportArgs& a, const Scene& loaded, const SolvedScene& solved, const Parts& p,
                                         const Json& frf, Embedder& em) {
  const ArticleScene& scene = std::get<ArticleScene>(loaded);
  std::vector<html::Section> out;
  out.push_back({"check", "Feasibility: " + p.check.json.at("overall").get<std::string>(), html::table(checkTable(p.check.json)),
                 checkAccuracy(p.check.json), {commandFor(a, "check", "--band " + a.band + " --out check")}});
  out.push_back({"strength", "Strength: stresses against allowables", html::table(strengthTable(p.modes.json, p.check.json)),
                 strengthAccuracy(p.modes.json), {commandFor(a, "modes", "--json"), commandFor(a, "check", "--json")}});
  const int sheet = std::min<int>(6, static_cast<int>(solved.modes.omega2.size()));
  out.push_back({"modes", "System modes about the held equilibrium",
                 html::table(modeTable(p.modes.json)) + (sheet > 0 ? modesSheet(scene, solved, sheet, em) : ""),
                 modesAccuracy(p.modes.json),
                 {commandFor(a, "modes", strf("--modes %d --out modes", a.modes)),
                  commandFor(a, "render", strf("--mode 1-%d --out modes.png", sheet))}});
  const std::string sensors = em.figures([&](const FigurePath& at) { writePlacementFigures(at, loaded, p.placement); },
                                         [](const std::string& name) {
                                           if (name == "automac.png") return std::string("AutoMAC of the target modes seen by the chosen sensors (0: told apart, 1: alike).");
                                           if (name == "review_sensors.png") return std::string("The chosen sensors on the article, coloured by their score.");
                                           return std::string("The target modes with the chosen sensors.");
                                         });
  out.push_back({"sensors", "Sensor plan", html::table(sensorTable(p.placement.json)) + "<div class=\"grid\">" + sensors + "</div>",
                 placementAccuracy(p.placement.json),
                 {commandFor(a, "place-sensors", strf("--below-hz %s --count %d --out sensors", shortest(parseBand(a.band).second).c_str(), a.sensors))}});
  const std::string bodes = em.figures([&](const FigurePath& at) { writeBodePlots(at, *p.frf, false); },
                                       [](const std::string& name) { return "Bode plot " + name.substr(5, name.size() - 9) + ": full and reduced model, the kept modes dotted."; });
  out.push_back({"frf", "Frequency responses", html::table(frfTable(frf)) + "<div class=\"grid\">" + bodes + "</div>",
                 frfAccuracy(frf), {commandFor(a, "frf", "--out frf")}});
  return out;
}

}  // namespace

int runReportCommand(const ReportArgs& args) {
  return guarded([&]() -> int {
    const Scene loaded = loadScene(args);
    OutputDir out(args.out, args.force);  // a bad --out refused before the work
    if (const auto* isolator = std::get_if<HamsasScene>(&loaded)) return runHamsasReport(args, *isolator, out);
    const Parts p = runParts(args, loaded);
    const Json frf = p.frf->frfJson();
    Embedder em(out);
    const ProgressStage stage("report: figures and page");
    const ArticleScene& scene = std::get<ArticleScene>(loaded);
    html::Page page;
    page.title = "Test-readiness report: " + scene.name;
    const Json& model = p.modes.json.at("model");
    page.subtitle = (args.scene_path.empty() ? std::string("embedded default scene") : args.scene_path) + " \u2014 " +
                    model.value("kind", "") + strf(" model, %d degrees of freedom, %.4g kg moving", model.value("dofs", 0),
                                                   model.value("moving_mass_kg", 0.0)) +
                    " \u2014 mmvlab " + mmvlabVersion();
    page.summary = summaryTiles(p.check.json, p.modes.json, p.placement.json, frf);
    const SolvedScene solved = solveScene(scene);
    page.sections.push_back(articleSection(args, scene, solved, em));
    for (auto& s : studySections(args, loaded, solved, p, frf, em)) page.sections.push_back(std::move(s));
    page.sections.push_back(sceneSection(args, scene.text));
    page.footer = "Made by " + commandFor(args, "report", "--out " + shellWord(args.out)) +
                  ". Every table is the JSON of the command under it (report.json holds them); the figures are those "
                  "commands' figures.";
    Json doc;
    doc["mmvlab_version"] = mmvlabVersion();
    doc["command"] = "report";
    doc["scene"] = {{"name", scene.name}, {"source", args.scene_path.empty() ? "<default scene>" : args.scene_path}};
    doc["figures"] = em.count();
    doc["check"] = p.check.json;
    doc["modes"] = p.modes.json;
    doc["placement"] = p.placement.json;
    doc["frf"] = frf;
    const std::string where = writeReport(out, args.out, page, doc);
    emitResult(strf("report: %s\n  check: %s\n  %zu modes tabulated, %zu sensors, %zu frequency-response pairs, %d figures\n",
                    scene.name.c_str(), p.check.json.at("overall").get<std::string>().c_str(), p.modes.json.at("modes").size(),
                    p.placement.json.at("chosen").size(), frf.at("pairs").size(), em.count()) + where);
    return kOk;
  });
}

CLI::App* addReportCommand(CLI::App& app, ReportArgs& r, const std::function<void(CLI::App*, SceneArgs&)>& scene_options) {
  CLI::App* c = app.add_subcommand("report", "One self-contained HTML page for a test-readiness review: renders, check's "
                                             "verdicts, modes, the sensor plan, FRFs, accuracy, the scene, the commands");
  scene_options(c, r);
  c->callback([c, &r] {  // the options given: a HAM-SAS page keeps its own band and count unless told
    for (const CLI::Option* o : c->get_options())
      if (o->count() > 0) r.given.insert(o->get_name());
  });
  c->add_option("--out", r.out, "Write report.html (self-contained: open it in any browser, print it to PDF) and report.json here")
      ->required();
  c->add_flag("--force", r.force, "Replace report.html and report.json in --out");
  c->add_option("--modes", r.modes, "Rows of the mode table, 1 .. 500")->capture_default_str()->check(CLI::Range(1, 500));
  c->add_option("--sensors", r.sensors, "Sensors in the plan (place-sensors --count), 1 .. the candidates (stations every 0.1 m, 2 directions); "
                                  "HAM-SAS: 12 unless given")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  c->add_option("--band", r.band, "The modes of interest, F_MIN_HZ:F_MAX_HZ: check's band and the sensor plan's targets "
                                  "(HAM-SAS: the modes below 5 Hz unless given)")
      ->capture_default_str();
  return c;
}

}  // namespace mmv::cli

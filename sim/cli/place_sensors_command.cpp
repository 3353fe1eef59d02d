// mmvlab place-sensors: choose sensor stations for the target modes
// (sim/modes/place_sensors.hpp), written by sim/io/placement_report.hpp; the AutoMAC
// heat map and the review renders (the chosen sensors on the article and on each
// target mode) by renders/.
#include <fstream>
#include <map>
#include <functional>
#include <optional>
#include <iostream>
#include <sstream>

#include "sim/app/plan_studies.hpp"
#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_placement.hpp"
#include "sim/view/article_drawing.hpp"
#include "sim/view/hamsas_drawing.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/placement_report.hpp"
#include "sim/model/stations.hpp"
#include "sim/modes/sensor_loading.hpp"

namespace mmv::cli {
namespace {

/// "1-8", "1,3,5-7" -> {1, ..., 8}.
std::vector<int> parseModeList(const std::string& text) {
  std::vector<int> out;
  std::stringstream ss(text);
  for (std::string part; std::getline(ss, part, ',');) {
    const auto dash = part.find('-');
    char *e1 = nullptr, *e2 = nullptr;
    const long a = std::strtol(part.c_str(), &e1, 10);
    const long b = dash == std::string::npos ? a : std::strtol(part.c_str() + dash + 1, &e2, 10);
    const bool ok = !part.empty() && (dash == std::string::npos ? *e1 == '\0' : (e1 == part.c_str() + dash && *e2 == '\0'));
    if (!ok || a < 1 || b < a || b > 100000)
      throw UsageError("--modes: expected mode numbers like 1-8 or 1,3,5-7 (got " + text + ")");
    for (long m = a; m <= b; ++m) out.push_back(static_cast<int>(m));
  }
  return out;
}

/// The review renders, for either kind of scene: the still drawing (`still`) with the
/// chosen sensors numbered as placement.json lists them (and the report's table), each
/// with its station, its measuring axes as rods and its score as colour, apart from the
/// scene's own sensors; and a contact sheet of the target modes (`mode(m)`) with the
/// sensors' numbers on them, seen from preset `view`.
void writeReviewRenders(const FigurePath& out, const PlacementStudy& s, const std::string& scene_name, DrawList d,
                        const std::function<DrawList(ModeNumber)>& mode, const std::string& view) {
  std::vector<Eigen::Vector3d> at;
  std::vector<std::string> names, numbers;
  std::vector<std::vector<Eigen::Vector3d>> axes;
  std::vector<double> scores;
  for (std::size_t i = 0; i < s.result.kept_blocks.size(); ++i) {
    const int block = s.result.kept_blocks[i];
    const PlacementCandidate& c = s.candidates[static_cast<std::size_t>(block)];
    at.push_back({c.world_x, c.world_y, c.world_z});
    numbers.push_back(std::to_string(i + 1));
    names.push_back(strf("%zu: %s %s%s", i + 1, c.station.c_str(), c.axis.c_str(), c.fixed ? " (kept)" : ""));
    axes.emplace_back();
    for (const auto& dir : s.directions)
      if (dir.block == block) axes.back().push_back({dir.world[0], dir.world[1], dir.world[2]});
    scores.push_back(s.result.block_score[i]);
  }
  const std::string score = s.method == "effective independence" ? "EfI" : "score";
  addProposedSensors(d, at, names, axes, scores, "chosen sensors, numbered (colour: " + score + "; rod: measuring axis)");
  d.has_color_bar = true;
  d.color_bar = {score, 0.0, s.result.block_score.maxCoeff()};
  d.title = strf("%s: %zu sensors by %s", scene_name.c_str(), at.size(), s.method.c_str());
  Camera camera;
  presetCamera(view, d.bounds(), camera, d.up);
  figures::framePng(out("review_sensors.png"), d, camera, {1280, 720, 3});
  std::vector<DrawList> tiles;
  std::vector<Camera> cameras;
  for (const ModeNumber m : s.target_modes) {
    DrawList md = mode(m);
    addProposedSensors(md, at, numbers, axes);
    Camera c;
    presetCamera(view, md.bounds(), c, md.up);
    tiles.push_back(std::move(md));
    cameras.push_back(c);
  }
  figures::contactSheetPng(out("review_modes.png"), tiles, cameras, {480, 320, 2}, std::min<int>(4, tiles.size()));
}

void writeArticleReviewRenders(const FigurePath& out, const ArticleScene& bare, const PlacementStudy& s,
                               const std::optional<ExciterStudy>& exciter) {
  // The model the study's target modes are of: the bare article, or the one carrying the
  // set the iterated placement settled on (its mode numbers and frequencies).
  const ArticleScene scene = s.carried.empty() ? bare : sceneWithSensors(bare, withNamedSet(s, s.carried), s.loading->sensor_mass_kg);
  const SolvedScene solved = solveScene(scene);
  SimTK::State st = solved.equilibrium.state;
  solved.model->getSystem().realize(st, SimTK::Stage::Position);
  DrawList still = drawArticle(scene, *solved.model, st);
  if (exciter && exciter->chosen) {  // `shaker.at: auto`: where the ranking put it
    std::string error;
    const auto at = PointRef::resolve(*solved.model, scene.article, exciter->at, error);
    if (!at) throw std::runtime_error("the chosen shaker attachment " + exciter->at + ": " + error);
    const SimTK::Vec3 p = at->position(st);
    addShakerDrawing(still, {p[0], p[1], p[2]}, {exciter->direction[0], exciter->direction[1], exciter->direction[2]},
                     strf("shaker at %s %s (ranked first)", exciter->at.c_str(), exciter->axis.c_str()));
  }
  writeReviewRenders(out, s, scene.name, std::move(still),
                     [&](ModeNumber m) { return ModeFrames(scene, solved, m, 0.0).frame(1.0, true); },
                     scene.article.model == ArticleModel::Spatial ? "iso" : "front");  // the front view hides z
}

void writeHamsasReviewRenders(const FigurePath& out, const HamsasScene& scene, const HamsasModes& unloaded, const PlacementStudy& s) {
  const HamsasModes h =
      s.carried.empty() ? unloaded : isolatorCarrying(unloaded, withNamedSet(s, s.carried), s.loading->sensor_mass_kg);
  auto bare = [](DrawList d) {
    d.labels.clear();  // the scene's own sensors would crowd the chosen ones
    return d;
  };
  writeReviewRenders(out, s, scene.name, bare(drawHamsas(scene, h)),
                     [&](ModeNumber m) { return bare(drawHamsas(scene, h, m, 1.0, 0.0, true)); }, "iso");
}

}  // namespace

void writePlacementFigures(const FigurePath& to, const Scene& loaded, const app::PlacementStudyResult& study, bool summary) {
  const PlacementStudy& s = study.study;
  std::map<std::string, std::string> staged;  // each figure staged once: the summary reads them back
  const FigurePath out = [&](const std::string& name) {
    const auto at = staged.find(name);
    return at != staged.end() ? at->second : staged[name] = to(name);
  };
  std::vector<std::string> rows, cols;
  for (std::size_t j = 0; j < s.target_modes.size(); ++j) {
    rows.push_back(strf("%d (%.3g Hz)", s.target_modes[j].number(), s.target_frequencies_hz[j]));
    cols.push_back(strf("%d %.3g Hz", s.target_modes[j].number(), s.target_frequencies_hz[j]));  // two lines under the column
  }
  try {
    figures::heatmap(out("automac.png"), s.result.automac, rows, cols,
                     strf("AutoMAC seen by %zu sensors (%s)", s.result.kept_blocks.size(), s.method.c_str()), "mode", "mode");
    if (const auto* article = std::get_if<ArticleScene>(&loaded)) writeArticleReviewRenders(out, *article, s, study.exciter);
    else writeHamsasReviewRenders(out, std::get<HamsasScene>(loaded), *study.isolator_modes, s);
    if (summary)  // one page: the sensors on the article, the AutoMAC, the modes, the verdicts
      figures::summaryPng(out("summary.png"), strf("%s: pre-test summary (place-sensors)", s.scene_name.c_str()),
                          {out("review_sensors.png"), out("automac.png"), out("review_modes.png")}, study.summary_lines);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

int runPlaceSensorsCommand(const PlaceSensorsArgs& args) {
  return guarded([&] {
    const Scene loaded = loadScene(args);
    app::PlacementRequest r;
    if (!args.modes.empty()) r.modes = parseModeList(args.modes);
    r.below_hz = args.below_hz;
    r.spacing_m = args.spacing;
    r.triaxial = args.triaxial;
    r.count = args.count;
    r.method = args.method;
    r.tam = args.tam;
    r.sensor_mass_kg = args.sensor_mass;
    r.min_separation_m = args.min_separation;
    r.keep_out = args.keep_out;
    r.channels = args.channels;
    r.keep_scene_sensors = args.keep_scene_sensors;
    r.instrument = args.instrument;
    r.iterate_loaded = args.iterate_loaded;
    r.strain_span_m = args.strain_span;
    r.max_deflection_m = args.max_deflection;
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const app::PlacementStudyResult study = app::runPlacementStudy(loaded, r);
    const PlacementStudy& s = study.study;
    if (out) {
      out->write("placement.json", study.json.dump(2) + "\n");
      out->write("candidates.csv", placementCandidatesCsv(s));
      out->write("automac.csv", placementAutoMacCsv(s));
      if (!study.tam_csv.empty()) out->write("tam.csv", study.tam_csv);
      if (study.tam_mat) writeMat(out->stage("tam.mat"), *study.tam_mat);
      if (!study.channels_csv.empty()) out->write("channels.csv", study.channels_csv);
      if (!study.geometry_uff.empty()) out->write("test_geometry.uff", study.geometry_uff);
      if (!study.sensors_vtp.empty()) out->write("sensors.vtp", study.sensors_vtp);
      if (!study.exciter_csv.empty()) out->write("exciter.csv", study.exciter_csv);
      if (!study.exciter_ranking_csv.empty()) out->write("exciter_ranking.csv", study.exciter_ranking_csv);
      writePlacementFigures([&](const std::string& name) { return out->stage(name); }, loaded, study, /*summary=*/true);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(study.json) : emitResult(study.text);
    return kOk;
  });
}

}  // namespace mmv::cli

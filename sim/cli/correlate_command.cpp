// mmvlab correlate: a measured modal test (UFF 58 FRFs, 55 mode shapes, 15/2411 nodes)
// against the scene's model (sim/linear/correlation.hpp).
#include <cmath>
#include <fstream>
#include <iostream>

#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/linear_report.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/uff_read.hpp"

namespace mmv::cli {
namespace {

MeasuredSet readMeasured(const std::string& path) {
  std::string text, why;
  if (!readInputFile(path, limits::kMaxMeasuredBytes, text, why)) throw SceneFileError(path + ": " + why);
  const uff::File file = uff::read(text, path);
  if (file.nodes.size() > static_cast<std::size_t>(limits::kMaxMeasuredNodes))
    throw SceneError(strf("%s: %zu nodes, more than the %d a correlation pairs with the article", path.c_str(),
                          file.nodes.size(), limits::kMaxMeasuredNodes));
  return measuredSet(file, path);
}

CorrelateOptions options(const CorrelateArgs& args, const ArticleScene& scene) {
  CorrelateOptions o;
  o.pair_distance_m = args.pair_distance;
  o.model_modes = args.modes;
  o.mac_threshold = args.mac_threshold;
  o.max_frequency_error = args.max_frequency_error;
  o.damping.modal_ratio = args.damping_ratio;
  if (scene.damping && !args.damping_given) o.damping = *scene.damping;
  for (const auto& p : args.pairs) {
    const auto eq = p.find('=');
    int node = 0;
    try {
      std::size_t used = 0;
      node = std::stoi(p.substr(0, eq), &used);
      if (used != eq) throw std::invalid_argument(p);
    } catch (const std::exception&) {
      throw UsageError("--pair " + p + ": expected NODE=POINT (a node label of the file, a point or station of the scene)");
    }
    if (eq == std::string::npos || eq + 1 >= p.size())
      throw UsageError("--pair " + p + ": expected NODE=POINT (a node label of the file, a point or station of the scene)");
    o.named_pairs.push_back({node, p.substr(eq + 1)});
  }
  return o;
}

void writeFigures(const CorrelationResult& r, const ArticleScene& scene, OutputDir& out) {
  std::vector<std::string> rows, cols;
  for (std::size_t i = 0; i < r.test_modes.size(); ++i) rows.push_back(modeLabel('T', static_cast<int>(i + 1), r.test_modes[i].frequency_hz));
  for (const auto& m : r.model_modes) cols.push_back(modeLabel('M', m.number, m.frequency_hz));
  std::vector<double> model_hz;
  for (const auto& m : r.model_modes)
    if (m.stable && !m.rigid_body) model_hz.push_back(m.frequency_hz);
  if (r.mac.size() > 0)
    figures::heatmap(out.stage("mac.png"), r.mac, rows, cols, "MAC, test against model: " + scene.name, "test mode",
                     "model mode");
  for (const auto& f : r.frfs) {
    if (!f.skipped.empty()) continue;
    render::BodeTrace test{"test (function " + std::to_string(f.index + 1) + ")"}, model{"model"};
    model.dashed = true;
    for (std::size_t k = 0; k < f.frequency_hz.size(); ++k) {
      for (auto* t : {&test, &model}) t->frequency.push_back(f.frequency_hz[k]);
      test.magnitude_db.push_back(20 * std::log10(std::abs(f.test[k]) + 1e-300));
      test.phase_deg.push_back(std::arg(f.test[k]) * 180 / M_PI);
      model.magnitude_db.push_back(20 * std::log10(std::abs(f.model[k]) + 1e-300));
      model.phase_deg.push_back(std::arg(f.model[k]) * 180 / M_PI);
    }
    const std::string name = strf("frf_%02d_", f.index + 1) + safeFileName(f.output) + "__" + safeFileName(f.input);
    figures::bode(out.stage(name + ".png"), {test, model},
                  strf("%s / %s: FRAC %.3f (%s)", f.output.c_str(), f.input.c_str(), f.frac, scene.name.c_str()),
                  "frequency (Hz)", model_hz);
  }
}

}  // namespace

int runCorrelateCommand(const CorrelateArgs& args) {
  return guarded([&] {
    const ArticleScene scene = loadArticleScene(args, "correlate");
    if (args.measured.empty()) throw UsageError("--measured: the measured UFF file is required");
    const CorrelateOptions opt = options(args, scene);  // command-line errors before the file is read
    const MeasuredSet test = readMeasured(args.measured);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const CorrelationResult r = correlate(scene, test, opt);
    const nlohmann::ordered_json json = correlationJson(scene, r);
    const std::string text = correlationText(scene, r);
    checkResultFinite(json);
    checkResultFinite(text);
    if (out) {
      out->write("correlation.json", json.dump(2) + "\n");
      out->write("mac.csv", macCsv(r));
      try {
        writeFigures(r, scene, *out);
      } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
      }
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(json) : emitResult(text);
    return kOk;
  });
}

}  // namespace mmv::cli

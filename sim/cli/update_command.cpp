// mmvlab update: scene values adjusted so that the model reproduces a measured modal
// test (sim/linear/model_update.hpp).
#include <iostream>
#include <optional>

#include "sim/app/update_study.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {
namespace {

void writeFigures(const ModelUpdateResult& r, OutputDir& out) {
  render::Series before{"before (nominal)"}, after{"after (updated)"}, zero{"test"};
  for (auto* s : {&before, &after}) s->markers_only = true;
  before.hollow = true;
  for (std::size_t k = 0; k < r.pairs.size(); ++k) {
    const UpdatePair& p = r.pairs[k];
    const double at = static_cast<double>(k + 1);
    before.x.push_back(at), before.y.push_back(100 * (p.before_hz / p.test_hz - 1));
    after.x.push_back(at), after.y.push_back(100 * (p.after_hz / p.test_hz - 1));
    after.point_labels.push_back(p.test);
    zero.x.push_back(at), zero.y.push_back(0);
  }
  zero.dashed = true;
  figures::linePlot(out.stage("frequency_errors.png"), {zero, before, after},
                    "Frequency error against the test, before and after: " + r.scene, "measured mode (tracked, in order)", "f_model / f_test - 1 (%)");
  render::Series mac_before{"before (nominal)"}, mac_after{"after (updated)"};
  for (auto* s : {&mac_before, &mac_after}) s->markers_only = true;
  mac_before.hollow = true;
  for (std::size_t k = 0; k < r.pairs.size(); ++k) {
    mac_before.x.push_back(static_cast<double>(k + 1)), mac_before.y.push_back(r.pairs[k].before_mac);
    mac_after.x.push_back(static_cast<double>(k + 1)), mac_after.y.push_back(r.pairs[k].after_mac);
    mac_after.point_labels.push_back(r.pairs[k].test);
  }
  figures::linePlot(out.stage("mac.png"), {mac_before, mac_after}, "MAC of each measured mode with its model mode: " + r.scene,
                    "measured mode (tracked, in order)", "MAC");
  render::Series cost{"cost 0.5 |r|^2"};
  for (const auto& it : r.fit.iterations) cost.x.push_back(it.iteration), cost.y.push_back(std::max(it.cost, 1e-300));
  figures::linePlot(out.stage("iterations.png"), {cost}, "Levenberg-Marquardt iterations: " + r.scene, "iteration",
                    "cost (weighted residuals)", true);
}

}  // namespace

int runUpdateCommand(const UpdateArgs& args) {
  return guarded([&] {
    app::LoadedScene loaded = app::loadScene(sceneRequest(args));
    for (const auto& w : loaded.warnings) std::cerr << w << '\n';
    app::UpdateRequest r;
    r.params = args.params;
    r.pairing.measured = args.measured;
    r.pairing.pair_distance_m = args.pair_distance;
    r.pairing.pairs = args.pairs;
    r.pairing.modes = args.modes;
    r.pairing.mac_threshold = args.mac_threshold;
    r.pairing.max_frequency_error = args.max_frequency_error;
    r.frequency_sigma = args.frequency_sigma;
    r.mac_sigma = args.mac_sigma;
    r.mac_residuals = !args.no_mac;
    r.regularization = args.regularization;
    r.max_iterations = args.max_iterations;
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
    const app::UpdateStudy s = app::runUpdateStudy(loaded, r);
    if (out) {
      out->write("update.json", s.json.dump(2) + "\n");
      out->write("updated_scene.yaml", s.result.updated_scene);
      out->write("parameters.csv", s.parameters_csv);
      out->write("pairs.csv", s.pairs_csv);
      out->write("iterations.csv", s.iterations_csv);
      try {
        writeFigures(s.result, *out);
      } catch (const std::runtime_error& e) {
        throw OutputError(e.what());
      }
      out->commit();
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli

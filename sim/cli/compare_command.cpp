// mmvlab compare: component modes against system modes (sim/modes/compare.hpp).
#include <fstream>
#include <iostream>

#include "sim/cli/figures.hpp"
#include "sim/app/component_studies.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/report_compare.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {
namespace {

void macPng(const std::string& path, const SynthesisResult& s, const std::string& title) {
  std::vector<std::string> rows, cols;
  for (Eigen::Index i = 0; i < s.mac.rows(); ++i) rows.push_back(strf("%ld: %.2f Hz", static_cast<long>(i + 1), s.synth_hz[i]));
  // Each full-model mode with its frequency ("3 4.41 Hz", drawn on two lines).
  for (Eigen::Index j = 0; j < s.mac.cols(); ++j)
    cols.push_back(j < s.full_hz.size() ? strf("%ld %.3g Hz", static_cast<long>(j + 1), s.full_hz[j]) : strf("%ld", static_cast<long>(j + 1)));
  try {
    figures::heatmap(path, s.mac, rows, cols, title, "synthesized mode", "full model's mode");
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runCompareCommand(const CompareArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    const auto r = declaredRequest<app::CompareRequest>(args);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);  // fail early, before the work
    const app::CompareStudy s = app::runCompareStudy(scene, r);
    const CompareReport& rep = s.report;
    if (out) {
      out->write("compare.md", s.markdown);
      for (const auto& [name, text] : compareCsvFiles(rep)) out->write(name, text);
      out->write("compare.json", s.json.dump(2) + "\n");
      macPng(out->stage("mac_assumed_modes.png"), rep.assumed, "MAC: " + rep.assumed.method + ": " + sceneName(scene));
      macPng(out->stage("mac_craig_bampton.png"), rep.craig_bampton, "MAC: " + rep.craig_bampton.method + ": " + sceneName(scene));
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli

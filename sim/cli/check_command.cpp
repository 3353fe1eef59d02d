// mmvlab check: the feasibility report (sim/plan/check.hpp), written by sim/io/check_report.hpp.
#include <fstream>
#include <iostream>

#include "sim/cli/commands.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {

int runCheckCommand(const CheckArgs& args) {
  return guarded([&] {
    const ArticleScene scene = loadArticleScene(args, "check");
    CheckOptions opt;
    opt.required_margin_pct = args.margin;
    std::tie(opt.band_min_hz, opt.band_max_hz) = parseBand(args.band);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const CheckReport rep = runCheck(scene, opt);
    if (out) {
      out->write("check.md", checkMarkdown(rep));
      out->write("check.json", checkJson(rep).dump(2) + "\n");
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(checkJson(rep)) : emitResult(checkText(rep));
    return kOk;
  });
}

}  // namespace mmv::cli

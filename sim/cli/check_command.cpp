// mmvlab check: the feasibility report (app::runCheckStudy), written by sim/io/check_report.hpp.
#include <iostream>

#include "sim/app/plan_studies.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {

int runCheckCommand(const CheckArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    const auto r = declaredRequest<app::CheckRequest>(args);
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const app::CheckStudy s = app::runCheckStudy(scene, r);
    if (out) {
      out->write("check.md", s.markdown);
      out->write("check.json", s.json.dump(2) + "\n");
      out->write("check.csv", checkCsv(s.report));
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    // A FAIL is the answer, not an error: the report is out; the code tells a script.
    return s.report.overall == Verdict::Fail && !args.report_only ? kCheckFailed : kOk;
  });
}

}  // namespace mmv::cli

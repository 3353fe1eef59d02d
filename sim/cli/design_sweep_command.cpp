// mmvlab sweep and sweep-merge: design sweeps (sim/scene/design_sweep_spec.hpp) evaluated by
// sim/app/design_sweep_points.hpp and run by sim/plan/design_sweep.hpp.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "sim/app/design_sweep_study.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/files.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/app/design_sweep_points.hpp"
#include "sim/plan/design_sweep.hpp"

namespace mmv::cli {
namespace {

/// --shard I/N, else Slurm's array variables, else the whole sweep.
Shard chooseShard(const std::string& text) {
  Shard s;
  if (!text.empty()) {
    char extra = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &s.index, &s.count, &extra) != 2 || s.count < 1 || s.index < 1 || s.index > s.count)
      throw UsageError("--shard: expected I/N with 1 <= I <= N (got '" + text + "')");
    return s;
  }
  const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
  const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
  if (!id || !count) return s;
  const char* min = std::getenv("SLURM_ARRAY_TASK_MIN");
  s.index = std::atoi(id) - (min ? std::atoi(min) : 0) + 1;
  s.count = std::atoi(count);
  if (s.count < 1 || s.index < 1 || s.index > s.count)
    throw UsageError(strf("SLURM_ARRAY_TASK_ID=%s, SLURM_ARRAY_TASK_COUNT=%s do not make a shard", id, count));
  return s;
}

}  // namespace

int runDesignSweepCommand(const DesignSweepArgs& args) {
  return guarded([&] {
    app::DesignSweepRequest r;
    r.spec = args.spec;
    r.out = args.out;
    r.jobs = args.jobs;
    r.shard = chooseShard(args.shard);
    r.restart = args.force;
    const app::DesignSweepStudy s = [&] {
      Progress progress("sweep, points done");
      r.progress = [&progress](long done, long total) { progress.report(double(done), double(total)); };
      return app::runDesignSweepStudy(r);
    }();
    // sweep.csv (the journal's table), the summary and the figures are one transaction:
    // all of them replace the last run's, or none; only files this sweep's folder's record
    // lists as mmvlab wrote them are replaced (checked before computing too).
    OutputDir out(s.dir, /*force=*/true);
    out.replaceOnlyOwnFiles();
    app::stageDesignSweepOutputs(s, out);
    if (r.shard.count == 1) writeDesignSweepPlots(s.result.table, out);
    out.commit();
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

int runSweepMergeCommand(const SweepMergeArgs& args) {
  return guarded([&] {
    OutputDir out(args.out, args.force);
    out.replaceOnlyOwnFiles();  // --force replaces an earlier merge's files, never a user's
    const std::string csv_target = (std::filesystem::path(args.out) / "sweep.csv").string();
    const app::DesignSweepStudy s = app::mergeDesignSweepStudy(args.shards, csv_target);
    app::stageDesignSweepOutputs(s, out);  // sweep.csv, sweep.json: as a local sweep stages them
    writeDesignSweepPlots(s.result.table, out);
    std::vector<std::string> figures = out.targets();
    const std::string csv = figures.front();
    figures.erase(figures.begin(), figures.begin() + 2);  // sweep.csv, sweep.json
    out.commit();
    if (args.json) {
      nlohmann::ordered_json j;
      j["command"] = "sweep-merge";
      j["shards"] = args.shards;
      j["csv"] = csv;
      j["summary"] = (std::filesystem::path(csv).parent_path() / "sweep.json").string();
      j["figures"] = figures;
      emitResult(j);
    } else {
      emitResult("merged " + std::to_string(args.shards.size()) + " shards into " + csv + " and sweep.json\n");
    }
    return kOk;
  });
}

}  // namespace mmv::cli

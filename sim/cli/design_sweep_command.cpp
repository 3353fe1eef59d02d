// mmvlab sweep and sweep-merge: design sweeps (sim/scene/sweep_spec.hpp) evaluated by
// sim/io/sweep_points.hpp and run by sim/plan/sweep_runner.hpp.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "sim/cli/commands.hpp"
#include "sim/core/files.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/io/sweep_points.hpp"
#include "sim/plan/sweep_runner.hpp"

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

nlohmann::ordered_json summary(const SweepContext& c, const SweepRun& run, const SweepRunResult& r) {
  nlohmann::ordered_json j;
  j["spec"] = c.spec.source;
  j["scene"] = c.scene_source;
  j["fingerprint"] = c.fingerprint;
  j["design"] = c.spec.design == SweepSpec::Design::Grid ? "grid" : "latin_hypercube";
  j["points"] = c.points.size();
  j["shard"] = run.shard.text();
  j["jobs"] = run.jobs;
  j["computed"] = r.computed;
  j["reused"] = r.reused;
  j["seconds"] = r.seconds;
  j["columns"] = c.header;
  j["csv"] = r.csv;
  return j;
}

}  // namespace

int runDesignSweepCommand(const DesignSweepArgs& args) {
  return guarded([&] {
    const SweepSpec spec = loadSweepSpec(args.spec);
    const Shard shard = chooseShard(args.shard);
    const SweepContext context = prepareSweep(spec);  // every key and output checked before anything is written
    SweepRun run;
    run.dir = shard.count > 1 ? (std::filesystem::path(args.out) / strf("shard-%d-of-%d", shard.index, shard.count)).string() : args.out;
    run.fingerprint = context.fingerprint;
    run.header = context.header;
    run.total_points = static_cast<long>(context.points.size());
    run.shard = shard;
    run.jobs = args.jobs > 0 ? args.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    run.evaluate = [&context](long i) { return evaluateSweepPoint(context, i); };
    const SweepRunResult r = [&] {
      Progress progress("sweep, points done");
      run.progress = [&progress](long done, long total) { progress.report(double(done), double(total)); };
      return runSweep(run, args.force);
    }();
    const nlohmann::ordered_json j = summary(context, run, r);
    // sweep.csv is the journal's table (runSweep wrote it whole); the summary and the
    // figures are one transaction on top of it: all of them replace the last run's, or none.
    OutputDir out(run.dir, /*force=*/true);
    out.write("sweep.json", j.dump(2) + "\n");
    if (shard.count == 1) writeSweepPlots(r.table, out);
    out.commit();
    if (args.json) {
      emitResult(j);
    } else {
      emitResult(strf("sweep %s: %zu points (%s), shard %s: %ld computed, %ld already done, %.2f s on %d threads\n",
                      spec.source.c_str(), context.points.size(), j["design"].get<std::string>().c_str(), shard.text().c_str(),
                      r.computed, r.reused, r.seconds, run.jobs) +
                 "wrote " + r.csv + "\n");
    }
    return kOk;
  });
}

int runSweepMergeCommand(const SweepMergeArgs& args) {
  return guarded([&] {
    OutputDir out(args.out, args.force);
    const std::string table = mergeSweepTables(args.shards);
    out.write("sweep.csv", table);
    writeSweepPlots(table, out);
    std::vector<std::string> figures = out.targets();
    const std::string csv = figures.front();
    figures.erase(figures.begin());
    out.commit();
    if (args.json) {
      nlohmann::ordered_json j;
      j["command"] = "sweep-merge";
      j["shards"] = args.shards;
      j["csv"] = csv;
      j["figures"] = figures;
      emitResult(j);
    } else {
      emitResult("merged " + std::to_string(args.shards.size()) + " shards into " + csv + "\n");
    }
    return kOk;
  });
}

}  // namespace mmv::cli

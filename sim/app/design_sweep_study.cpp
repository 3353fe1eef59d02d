#include "sim/app/design_sweep_study.hpp"

#include <algorithm>
#include <filesystem>
#include <thread>

#include "sim/core/files.hpp"
#include "sim/core/progress.hpp"
#include "sim/core/text.hpp"
#include "sim/app/design_sweep_points.hpp"

namespace mmv::app {

DesignSweepStudy runDesignSweepStudy(const DesignSweepRequest& r) {
  if (r.out.empty()) throw UsageError(optionName(r.front, "--out") + ": the sweep's directory is required");
  checkRange(r.front, "--jobs", r.jobs, 0, 1024);
  if (r.shard.count < 1 || r.shard.index < 1 || r.shard.index > r.shard.count)
    throw UsageError(strf("%s: expected I/N with 1 <= I <= N (got %d/%d)", optionName(r.front, "--shard").c_str(),
                          r.shard.index, r.shard.count));
  const DesignSweepSpec spec = loadSweepSpec(r.spec);
  const DesignSweepContext context = prepareDesignSweep(spec);  // every key and output checked before anything is written
  DesignSweepRun run;
  run.dir = r.shard.count > 1 ? (std::filesystem::path(r.out) / strf("shard-%d-of-%d", r.shard.index, r.shard.count)).string()
                              : r.out;
  run.fingerprint = context.fingerprint;
  run.header = context.header;
  run.total_points = static_cast<long>(context.points.size());
  run.shard = r.shard;
  run.jobs = r.jobs > 0 ? r.jobs : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  run.evaluate = [&context](long i) { return evaluateDesignSweepPoint(context, i); };
  run.progress = [&r](long done, long total) {
    progressCount(done, total, "point");
    if (r.progress) r.progress(done, total);
  };
  checkOwnOutputs(run.dir, designSweepOutputNames(context.header));  // before computing
  DesignSweepStudy s;
  {
    const ProgressStage stage("sweep points");
    s.result = runDesignSweep(run, r.restart);
  }
  s.dir = run.dir;
  s.jobs = run.jobs;
  auto& j = s.json;
  j["spec"] = context.spec.source;
  j["scene"] = context.scene_source;
  j["fingerprint"] = context.fingerprint;
  j["design"] = context.spec.design == DesignSweepSpec::Design::Grid ? "grid" : "latin_hypercube";
  j["points"] = context.points.size();
  j["shard"] = run.shard.text();
  j["jobs"] = run.jobs;
  j["computed"] = s.result.computed;
  j["reused"] = s.result.reused;
  j["seconds"] = s.result.seconds;
  j["columns"] = context.header;
  j["fields"] = sweepFieldsJson(context.columns);
  j["csv"] = s.result.csv;
  s.text = strf("sweep %s: %zu points (%s), shard %s: %ld computed, %ld already done, %.2f s on %d threads\n",
                spec.source.c_str(), context.points.size(), j["design"].get<std::string>().c_str(), run.shard.text().c_str(),
                s.result.computed, s.result.reused, s.result.seconds, run.jobs) +
           "wrote " + s.result.csv + "\n";
  return s;
}

std::vector<std::string> designSweepOutputNames(const std::vector<std::string>& header) {
  std::vector<std::string> names = {"sweep.csv", "sweep.json", "pareto.csv", "pareto.png", "frequency_map.png"};
  for (std::size_t c = 1; c < header.size() && header[c] != "status"; ++c) {
    names.push_back("frequencies_vs_" + fileNameSafe(header[c]) + ".png");
    names.push_back("margins_vs_" + fileNameSafe(header[c]) + ".png");
  }
  return names;
}

void stageDesignSweepOutputs(const DesignSweepStudy& s, OutputDir& out) {
  out.write("sweep.csv", s.result.table);
  out.write("sweep.json", s.json.dump(2) + "\n");
}

DesignSweepStudy mergeDesignSweepStudy(const std::vector<std::string>& dirs, const std::string& csv_path) {
  DesignSweepStudy s;
  s.result.table = mergeSweepTables(dirs);
  s.result.csv = csv_path;
  nlohmann::ordered_json merged;
  long computed = 0, reused = 0;
  double seconds = 0;
  int jobs = 1;
  for (const std::string& d : dirs) {
    const std::string path = (std::filesystem::path(d) / "sweep.json").string();
    std::string text, why;
    if (!readInputFile(path, 64L << 20, text, why))
      throw OutputError(path + ": " + why + " (a shard writes it when its last point is done: run the shard again to finish it)");
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(text, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded() || !j.is_object() || !j.contains("fingerprint") || !j["fingerprint"].is_string() ||
        !j.contains("computed") || !j["computed"].is_number_integer() || !j.contains("reused") ||
        !j["reused"].is_number_integer() || !j.contains("seconds") || !j["seconds"].is_number() || !j.contains("jobs") ||
        !j["jobs"].is_number_integer())
      throw OutputError(path + ": not a shard's sweep.json (it lacks fingerprint, computed, reused, seconds or jobs)");
    if (j["fingerprint"].get<std::string>() != readSweepJournal(d).fingerprint)
      throw OutputError(path + ": belongs to another sweep than " + d + "/journal.csv (run the shard again)");
    computed += j["computed"].get<long>();
    reused += j["reused"].get<long>();
    seconds += j["seconds"].get<double>();
    jobs = std::max(jobs, j["jobs"].get<int>());
    if (merged.is_null()) merged = std::move(j);
  }
  merged["shard"] = Shard{}.text();
  merged["jobs"] = jobs;
  merged["computed"] = computed;
  merged["reused"] = reused;
  merged["seconds"] = seconds;
  merged["csv"] = csv_path;
  merged["merged_from"] = dirs;
  s.json = std::move(merged);
  s.jobs = jobs;
  return s;
}

}  // namespace mmv::app

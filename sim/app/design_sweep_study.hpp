#pragma once
/// `sweep`: a design sweep over scene keys (sim/scene/design_sweep_spec.hpp), each point's
/// modes, check and fields evaluated by sim/app/design_sweep_points.hpp, run in parallel,
/// resumably and in shards by sim/plan/design_sweep.hpp into DIR (journal.csv,
/// sweep.csv). (`sweep-config`, the configuration walk, is sim/modes/config_sweep.hpp.)

#include <functional>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/plan/design_sweep.hpp"

namespace mmv::app {

struct DesignSweepRequest {
  std::string spec;    ///< the sweep spec file.
  std::string out;     ///< DIR: the journal and sweep.csv (a shard's: DIR/shard-I-of-N).
  int jobs = 0;        ///< threads, 0 .. 1024 (0: every core).
  Shard shard;         ///< 1/1: the whole sweep.
  bool restart = false;  ///< a journal of another sweep in DIR is emptied (else refused)
  std::function<void(long done, long total)> progress;
  Front front = Front::Cli;
};

struct DesignSweepStudy {
  DesignSweepRunResult result;  ///< sweep.csv's path and contents
  std::string dir;        ///< where the journal and sweep.csv are
  int jobs = 1;
  nlohmann::ordered_json json;  ///< sweep.json
  std::string text;
};

/// Checks, before computing, that DIR holds no file of the sweep's outputs' names that
/// mmvlab did not write there (designSweepOutputNames against DIR's outputs record,
/// sim/io/output_dir.hpp: a user's file, folder or link is refused with or without
/// --force), runs or resumes the sweep (the journal) and makes sweep.json; the outputs
/// themselves are the caller's to commit (stageDesignSweepOutputs), so that they are
/// placed with its figures in one transaction.
DesignSweepStudy runDesignSweepStudy(const DesignSweepRequest& request);

/// Every name a sweep of these columns may write into its folder: sweep.csv,
/// sweep.json, pareto.csv, pareto.png, frequency_map.png, and per parameter
/// frequencies_vs_<key>.png and margins_vs_<key>.png.
std::vector<std::string> designSweepOutputNames(const std::vector<std::string>& header);

/// sweep.csv and sweep.json staged into `out` (an OutputDir on study.dir that replaces
/// only its own files).
void stageDesignSweepOutputs(const DesignSweepStudy& study, OutputDir& out);

/// `sweep-merge`: the shards' journals joined into the table an unsharded run writes
/// (mergeSweepTables' checks) and its sweep.json, made from the shards' own: the same
/// keys as a local sweep's, with shard "1/1", computed, reused and seconds summed over
/// the shards, jobs their largest, `csv` = `csv_path`, and `merged_from` the shard
/// directories. A shard without a sweep.json (it never finished), or whose sweep.json
/// names another sweep than its journal, is refused by name (OutputError).
DesignSweepStudy mergeDesignSweepStudy(const std::vector<std::string>& shard_dirs, const std::string& csv_path);

}  // namespace mmv::app

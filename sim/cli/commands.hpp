#pragma once
/// The mmvlab subcommands: each wires a scene to an analysis and a writer. Output is
/// composed completely in memory and written only on success, so a failing run
/// writes nothing to stdout; diagnostics go to stderr.

#include <functional>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/cli/huge_pages.hpp"
#include "sim/app/component_studies.hpp"
#include "sim/app/config_sweep_study.hpp"
#include "sim/app/linear_study.hpp"
#include "sim/app/modes_study.hpp"
#include "sim/app/plan_studies.hpp"
#include "sim/app/simulate_study.hpp"
#include "sim/app/trade_study.hpp"
#include "sim/app/study.hpp"
#include "sim/core/errors.hpp"
#include "sim/modes/components.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/scene/scene.hpp"
#include "sim/linear/state_space.hpp"

namespace CLI {
class App;
}

namespace mmv {
class OutputDir;
struct SimulationResult;
}  // namespace mmv

namespace mmv::cli {

/// Exit codes (sysexits.h where one fits).
enum ExitCode : int {
  kOk = 0,
  kNumericalFailure = 1,  ///< the analysis could not produce trustworthy numbers.
  kCheckFailed = 3,       ///< check: a requirement FAILs (the report is written in full; --report-only: 0).
  kUsage = 64,            ///< bad command line.
  kDataError = 65,        ///< bad scene content.
  kNoInput = 66,          ///< the scene file is missing or unreadable.
  kUnavailable = 69,      ///< a part of the installation is missing (the SUNDIALS plugin).
  kInternal = 70,         ///< a bug: please report it.
  kCannotCreate = 73,     ///< the output cannot be written (or would replace files).
  kIoError = 74,          ///< standard output cannot be written (a full disk, a closed pipe).
};

struct SceneArgs {
  std::string scene_path;  ///< empty: the embedded default scene.
  std::optional<int> segments;  ///< every flexible link's segment count (a patch the scene reader checks)
  bool no_gravity = false; ///< analyse without gravity (as the report's TREETOPS run).
  std::vector<std::string> sets;  ///< --set KEY=VALUE overrides of scene keys.
  bool strict = false;            ///< implausible values (sim/scene/plausibility.hpp) are errors, not warnings.
  std::set<std::string> given;    ///< the options given on the command line ("--duration"), filled by main
};

/// What every verb that writes a result takes besides its declared options: --json,
/// --out DIR and --force.
struct OutputArgs {
  bool json = false;   ///< print JSON instead of text
  std::string out;     ///< also write the verb's files here
  bool force = false;  ///< replace files of the same names in --out
};

/// A verb's command line: the scene's options, the output's and the verb's own, declared
/// once in sim/app (sim/app/options.hpp) and added by sim/cli/declared_options.hpp.
template <class Options>
struct DeclaredArgs : SceneArgs, OutputArgs {
  Options options;
};

/// The study's request of a declared verb: its options as parsed (the request derives
/// from them), for the study to check.
template <class Request, class Options>
Request declaredRequest(const DeclaredArgs<Options>& a) {
  Request r;
  static_cast<Options&>(r) = a.options;
  return r;
}

using ModesArgs = DeclaredArgs<app::ModesParams>;
using ConvergeArgs = DeclaredArgs<app::ConvergeParams>;
using CompareArgs = DeclaredArgs<app::CompareParams>;
using ConfigSweepArgs = DeclaredArgs<app::ConfigSweepParams>;
/// check's command line: its declared options and the command line's own exit rule.
struct CheckArgs : DeclaredArgs<app::CheckParams> {
  bool report_only = false;  ///< exit 0 even when a requirement FAILs.
};
using SimulateArgs = DeclaredArgs<app::SimulateParams>;
using TradeArgs = DeclaredArgs<app::TradeParams>;

struct LinearArgs : SceneArgs {
  std::vector<std::string> inputs, outputs;  ///< see docs/outputs.md; empty: defaults.
  double f_min = 0.01, f_max = 100;          ///< Hz.
  bool range_given = false;  ///< --from or --to given: the grid is theirs even with --band.
  int points = 400;
  int rom_modes = 8;
  std::string band;  ///< "F1:F2" (Hz): keep the modes in the band instead.
  bool no_residualize = false;
  double damping_ratio = 0.01;
  bool damping_given = false;  ///< --damping overrides the scene's damping.
  bool rad = false;
  std::vector<std::string> vary;  ///< HAM-SAS frf: one "KEY=V1,V2,...".
  bool json = false;  ///< the summary as JSON (frf), rom.json on stdout (rom).
  double rom_target = 0.01;  ///< peak-normalized error the modes-needed count is for (0: not computed).
  double target_error = 0;   ///< > 0: segments and kept modes chosen for it (frf/rom --target-error)
  double time_budget = 0;    ///< s; > 0: --target-error's choice of segments within it
  std::string out;
  bool force = false;
};

struct PlaceSensorsArgs : SceneArgs {
  bool json = false;
  std::string modes;       ///< "1-8"; empty: every mode below below_hz.
  double below_hz = 50;
  double spacing = 0.1;    ///< m between candidate stations.
  int count = 8;
  bool triaxial = false;
  std::string method = "efi";
  std::vector<std::string> tam;  ///< guyan, irs, serep, all; empty: none
  double sensor_mass = 0;        ///< kg per sensor; 0: the sensors' masses left out
  double min_separation = 0;     ///< m; 0: none
  std::vector<std::string> keep_out;  ///< LINK:FROM:TO
  int channels = 0;              ///< the budget; 0: --count decides
  bool keep_scene_sensors = false;  ///< --keep-scene-sensors
  std::string instrument;        ///< --instrument NAME (the scene's instruments:)
  bool iterate_loaded = false;   ///< --iterate-loaded
  double strain_span = 0;        ///< --strain-span M; 0: accelerometers
  double max_deflection = 0;     ///< --max-deflection M; 0: none
  std::string out;
  bool force = false;
};

struct RenderArgs : SceneArgs {
  std::string view;  ///< empty: front, or iso for the spatial article.
  std::string mode;          ///< "", "K" or "K1-K2".
  double scale = 0;          ///< m of drawing per unit modal coordinate; 0: automatic.
  std::string size = "1280x720";
  std::string out;
  bool force = false;
  std::string history;              ///< a `simulate --out` directory: draw the run.
  double fps = 30, speed = 1;       ///< history videos: frames per second; run seconds per video second.
  double at = -1;                   ///< history stills: the run time (s); < 0: the run's end.
  std::vector<std::string> traces;  ///< history: history.csv columns (or sensor names) shown in an inset.
};

struct ReportArgs : SceneArgs {
  std::string out;  ///< report.html (self-contained) and report.json here.
  bool force = false;
  int modes = 12;         ///< rows of the mode table
  int sensors = 8;        ///< the sensor plan's count (place-sensors --count)
  std::string band = "0.1:50";  ///< Hz: check's band; the sensor plan's target modes are those in it
};

struct CorrelateArgs : SceneArgs {
  std::string measured;            ///< the measured UFF file.
  std::string tam;                 ///< --tam FILE[:METHOD]
  bool json = false;
  double pair_distance = 0.05;     ///< m: farther nodes are not paired.
  std::vector<std::string> pairs;  ///< NODE=POINT, by the user.
  int modes = 20;                  ///< model modes compared.
  double mac_threshold = 0.7;
  double max_frequency_error = 0.3;  ///< |f_model / f_test - 1| above it: not a pair.
  double damping_ratio = 0.01;
  bool damping_given = false;      ///< --damping overrides the scene's damping.
  std::string out;
  bool force = false;
};

struct UpdateArgs : CorrelateArgs {
  std::vector<std::string> params;  ///< KEY or KEY:LO:HI
  double frequency_sigma = 0.01;
  double mac_sigma = 0.05;
  bool no_mac = false;              ///< leave (1 - MAC) out of the residuals
  double regularization = 0;
  int max_iterations = 30;
};

struct DesignSweepArgs {
  std::string spec;    ///< the sweep spec (YAML).
  std::string out;     ///< the results directory (resumed when it holds this sweep).
  int jobs = 0;        ///< threads; 0: every core.
  std::string shard;   ///< "I/N"; empty: SLURM_ARRAY_TASK_ID/COUNT if set, else the whole sweep.
  bool force = false;  ///< start over in a directory that holds another sweep.
  bool json = false;
};

struct SweepMergeArgs {
  std::vector<std::string> shards;
  std::string out;
  bool force = false;
  bool json = false;
};

/// `render --history`: frames of a time run (sim/cli/render_history.cpp).
void renderHistory(const RenderArgs& args, const std::string& ext);

int runModesCommand(const ModesArgs& args);
int runCheckCommand(const CheckArgs& args);
int runCorrelateCommand(const CorrelateArgs& args);
int runUpdateCommand(const UpdateArgs& args);
int runDesignSweepCommand(const DesignSweepArgs& args);
int runSweepMergeCommand(const SweepMergeArgs& args);
/// The figures of a sweep's table (sweep.csv's text; sim/cli/design_sweep_plots.cpp), staged in `out`.
void writeDesignSweepPlots(const std::string& csv_text, OutputDir& out);
int runRenderCommand(const RenderArgs& args);
int runPlaceSensorsCommand(const PlaceSensorsArgs& args);
int runReportCommand(const ReportArgs& args);
/// `mmvlab report` and its options; `scene_options` adds the scene's (main.cpp's).
CLI::App* addReportCommand(CLI::App& app, ReportArgs& r, const std::function<void(CLI::App*, SceneArgs&)>& scene_options);

/// Where a figure named NAME is written: OutputDir::stage for a command's own files,
/// OutputDir::scratch for the figures a report embeds.
using FigurePath = std::function<std::string(const std::string& name)>;
/// place-sensors' figures: automac.png, review_sensors.png, review_modes.png.
/// automac.png and the review renders; with `summary` also summary.png, the one-page
/// summary of them and the study's verdicts (place-sensors; the report has its own page).
void writePlacementFigures(const FigurePath& out, const Scene& loaded, const app::PlacementStudyResult& study, bool summary = false);
/// frf's Bode plot of every input-output pair, full and reduced: bode_OUT__IN.png.
void writeBodePlots(const FigurePath& out, const app::LinearStudy& a, bool rad);
/// HAM-SAS frf's figures: transmissibility_horizontal.png, _tilt_to_horizontal.png,
/// _vertical.png, _angular.png, _10hz.png (the 6 x 6 at 10 Hz) and, with a varied
/// parameter, _vary.png.
void writeTransmissibilityPlots(const FigurePath& out, const std::string& name, const std::vector<double>& f,
                                const std::vector<Eigen::MatrixXcd>& T, const Eigen::MatrixXcd& T10,
                                const std::string& vary_key, const std::vector<HamsasVaryPoint>& varied,
                                const std::string& vary_unit);
/// "OUT__IN" of a pair's file names (frf_OUT__IN.csv, bode_OUT__IN.png).
std::string bodeFileBase(const StateSpace& s, Eigen::Index output, Eigen::Index input);
int runTradeCommand(const TradeArgs& args);
int runSimulateCommand(const SimulateArgs& args);
/// simulate --out's figures (sim/cli/simulate_plots.cpp): torques.png (each torquer
/// against its capacity), table.png (the actuator's force, the weight carried and the
/// payload rating), tips.png (tip displacements, mm), sensors.png (each sensor in % of
/// its range); each only when the run has what it shows.
void writeSimulationPlots(OutputDir& out, const SimulationResult& r, const std::string& title);
int runFrfCommand(const LinearArgs& args);
int runRomCommand(const LinearArgs& args);
int runConfigSweepCommand(const ConfigSweepArgs& args);
int runCompareCommand(const CompareArgs& args);
int runConvergeCommand(const ConvergeArgs& args);
int runSceneCommand();

// HAM-SAS isolator scenes (sim/cli/hamsas_command.cpp).
int runHamsasFrf(const LinearArgs& args, const HamsasScene& scene);
int runHamsasRom(const LinearArgs& args, const HamsasScene& scene);
/// --rom-modes / --band / --no-residualize as reduction options.
/// The frf/rom options as the study layer's request (--band parsed; ranges checked by the study).
app::LinearRequest linearRequest(const LinearArgs& args);
// Shared by the command implementations.
/// The scene (file or embedded default) with --segments and --no-gravity applied
/// (app::loadScene; its warnings printed on stderr); the command dispatches on its kind
/// once. UsageError for options that do not apply.
Scene loadScene(const SceneArgs& args);
/// The scene options as the study layer's request.
app::SceneRequest sceneRequest(const SceneArgs& args);
/// The article scene of `command` (a HAM-SAS scene is a UsageError), planar or spatial.
ArticleScene loadArticleScene(const SceneArgs& args, const std::string& command);
using app::checkedPoints;
/// --band F_MIN_HZ:F_MAX_HZ as (min, max); UsageError unless 0 <= min < max.
std::pair<double, double> parseBand(const std::string& band);
/// Runs `body`, turning the error classes into messages on stderr and exit codes.
int guarded(const std::function<int()>& body);

/// Prints a command's result (text, or JSON with two-space indent) on standard output,
/// after the last check that no NaN or inf reaches an output: one found throws a
/// NumericalError that names where (the line, or the JSON path), and nothing is printed.
void emitResult(const std::string& text);
void emitResult(const nlohmann::ordered_json& json);
/// The same check alone, for a command that must refuse before it commits its --out files.
using app::checkResultFinite;

}  // namespace mmv::cli

// mmvlab: ground-test planning for flexible multibody test articles.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "sim/app/verbs.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/declared_options.hpp"
#include "sim/cli/progress.hpp"
#include "sim/core/progress.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace {

using namespace mmv::cli;

/// A finite number above 0 (or at least 0), named in the message without CLI11's
/// 309-digit upper bound.
CLI::Validator positive(bool zero_allowed = false) {
  return CLI::Validator(
      [zero_allowed](std::string& v) {
        char* end = nullptr;
        const double x = std::strtod(v.c_str(), &end);
        const bool ok = end != v.c_str() && *end == '\0' && std::isfinite(x) && (zero_allowed ? x >= 0 : x > 0);
        if (ok) return std::string();
        return "must be a finite number " + std::string(zero_allowed ? "of at least 0" : "above 0") + ", got '" + v + "'";
      },
      zero_allowed ? "NONNEGATIVE" : "POSITIVE");
}

void addSceneOptions(CLI::App* cmd, mmv::cli::SceneArgs& a) {
  cmd->add_option("scene", a.scene_path, "Scene file (YAML); default: the embedded MMV article scene")
      ->check(CLI::Validator(
          [](std::string& v) { return v.empty() ? std::string("empty scene path (omit it for the embedded default scene)") : ""; },
          "PATH"));
  cmd->add_option("--segments", a.segments,
                  "Segments per flexible link, 1 .. " + std::to_string(mmv::limits::kMaxSegments) +
                      ", overriding the scene (each flexible link's segments:, checked as if in the file)");
  cmd->add_flag("--no-gravity", a.no_gravity, "Set gravity to zero (the report's TREETOPS run had none)");
  cmd->add_option("--set", a.sets,
                  "KEY=VALUE: override a scene key (repeatable), e.g. links.link1.length=2.5, joints.joint2.angle_deg=15; "
                  "checked as if it were in the file")
      ->allow_extra_args(false);
  cmd->add_flag("--strict", a.strict,
                "Refuse a scene with an implausible value (a likely unit slip, warned on stderr otherwise): exit 65");
}

/// --json, --out and --force; `out_help` names the files --out receives.
void addOutputOptions(CLI::App* cmd, OutputArgs& a, const std::string& out_help, const char* json_help = "Print JSON instead of tables") {
  cmd->add_flag("--json", a.json, json_help);
  cmd->add_option("--out", a.out, out_help);
  cmd->add_flag("--force", a.force, "Replace files of the same names in --out");
}

/// A declared verb's subcommand (sim/app/verbs.hpp): its summary, the scene's options, its
/// own (sim/cli/declared_options.hpp) and the output's.
template <class Options>
CLI::App* addDeclaredCommand(CLI::App& app, const std::string& name, DeclaredArgs<Options>& a) {
  const mmv::app::VerbDeclaration& verb = mmv::app::declaredVerb(name);
  CLI::App* cmd = app.add_subcommand(name, verb.summary);
  addSceneOptions(cmd, a);
  addDeclaredOptions(cmd, a.options);
  addOutputOptions(cmd, a, "Also write " + verb.outputs + " here", "Print JSON (docs/outputs.md) instead of tables");
  return cmd;
}

/// `mmvlab frf` and `mmvlab rom` (one set of options).
std::pair<CLI::App*, CLI::App*> addLinearCommands(CLI::App& app, LinearArgs& lin) {
  auto addLinear = [&](CLI::App* cmd) {
    addSceneOptions(cmd, lin);
    cmd->add_option("--input", lin.inputs, "table_x, table_y, table_z (spatial model), torque:JOINT, force:POINT:x|y|z, moment:POINT:rx|ry|rz, "
                    "shaker (the scene's, with its armature) (default: table_x, table_y)");
    cmd->add_option("--output", lin.outputs,
                    "POINT:x|y|z|rx|ry|rz[:disp|vel|acc|acc_abs] (z, rx, ry: spatial model; default: every link tip, absolute "
                    "acceleration), strain:STATION:STATION[:in|out], the mean bending strain over a span of one link (a "
                    "gauge or piezo film; out: bending out of the plane, spatial model), or stress:STATION[:+y|-y|+z|-z], "
                    "the bending stress at a station on a face (Pa; +y the default; z: spatial model)");
    cmd->add_option("--from", lin.f_min, "Lowest frequency, Hz")->capture_default_str();
    cmd->add_option("--to", lin.f_max, "Highest frequency, Hz")->capture_default_str();
    cmd->add_option("--points", lin.points, "Log-spaced frequencies, 2 .. 100000")->capture_default_str();
    cmd->add_option("--rom-modes", lin.rom_modes, "Modes kept in the reduced model, 1 .. 10000")->capture_default_str();
    cmd->add_option("--band", lin.band, "Keep the modes in F_MIN_HZ:F_MAX_HZ instead of --rom-modes");
    cmd->add_flag("--no-residualize", lin.no_residualize, "Truncate without static residualization");
    cmd->add_option("--damping", lin.damping_ratio, "Modal damping ratio of every mode, 0 .. 1 (default: the scene's damping, else 0.01)")->capture_default_str();
    cmd->add_flag("--json", lin.json, "Print the summary as JSON (docs/outputs.md)");
    cmd->add_option("--rom-target", lin.rom_target,
                    "Report how many modes a reduced model needs for this FRF error relative to each pair's peak, 0 .. 1 (0: skip)")
        ->capture_default_str();
    cmd->add_option("--target-error", lin.target_error,
                    "FRF error to meet relative to each pair's peak, e.g. 0.05: half for the mesh (every frequency up to --to "
                    "within half of it times the least damping ratio, at most 128 segments per link), half for the reduced "
                    "model (the fewest modes within it); 1e-12 .. 0.5");
    cmd->add_option("--time-budget", lin.time_budget, "Wall seconds --target-error may take choosing the segments");
    cmd->add_option("--out", lin.out, "Output directory");
    cmd->add_flag("--force", lin.force, "Replace files of the same names in --out");
  };
  CLI::App* fr = app.add_subcommand("frf", "Frequency responses and transmissibilities, full and reduced; CSV and Bode plots");
  addLinear(fr);
  fr->add_flag("--rad", lin.rad, "Plot against rad/s instead of Hz");
  fr->add_option("--vary", lin.vary, "HAM-SAS: one parameter over values, KEY=V1,V2,... (e.g. counterweight_mass=0,3.5,7)")->expected(1);
  CLI::App* ro = app.add_subcommand("rom", "Reduced-order state-space model for control design, as .mat (Octave/MATLAB ss)");
  addLinear(ro);
  return {fr, ro};
}

/// `mmvlab place-sensors` and its options.
CLI::App* addPlaceSensorsCommand(CLI::App& app, PlaceSensorsArgs& ps) {
  CLI::App* p = app.add_subcommand("place-sensors",
                                   "Sensor stations for the target modes: effective independence, kinetic energy or residue; "
                                   "on a scene with a shaker: its attachment, armature loading and levels (docs/pretest.md)");
  addSceneOptions(p, ps);
  p->add_flag("--json", ps.json, "Print JSON instead of tables");
  CLI::Option* target_modes =
      p->add_option("--modes", ps.modes, "Target modes, e.g. 1-8 or 1,3,5-7 (default: every mode below --below-hz)");
  p->add_option("--below-hz", ps.below_hz, "Target every vibration mode below this frequency, Hz (not with --modes)")
      ->capture_default_str()
      ->excludes(target_modes);  // one rule chooses the targets, never one silently over the other
  p->add_option("--count", ps.count, "Sensors to place (triaxial: blocks), 1 .. 100000")->capture_default_str();
  p->add_option("--spacing", ps.spacing, "Distance between candidate stations along each link, 0.001 .. 100 m")
      ->capture_default_str();
  p->add_flag("--triaxial", ps.triaxial, "Place triaxial blocks (kept or removed whole) instead of uniaxial sensors");
  p->add_option("--method", ps.method, "efi (effective independence), mke (modal kinetic energy) or dpr (driving-point residue)")
      ->capture_default_str();
  p->add_option("--min-separation", ps.min_separation,
                "No two chosen stations closer than this, m (0 .. 100; one station's directions excepted)");
  p->add_option("--keep-out", ps.keep_out, "LINK:FROM_M:TO_M: a stretch of a link no sensor may go on (repeatable)");
  p->add_option("--channels", ps.channels,
                "The budget in channels: sets --count (a triaxial block takes 3)");
  p->add_flag("--keep-scene-sensors", ps.keep_scene_sensors,
              "Keep the scene's own accelerometers (at stations, or links' roots and tips), counted in --count, and choose "
              "the others around them");
  p->add_option("--sensor-mass", ps.sensor_mass,
                "Each chosen sensor's mass, kg (0 .. 100; a triaxial block counts one): welded at its station and the "
                "modes solved again, each target's shift beside first-order perturbation theory (default: the instrument's)");
  p->add_option("--instrument", ps.instrument,
                "The accelerometer placed, from the scene's instruments: (default: accelerometer, the report's): its mass loads "
                "the model, its range and resolution set the shaker's levels, a triaxial one (axes: 3) places blocks");
  p->add_flag("--iterate-loaded", ps.iterate_loaded, "Place again on the model carrying the sensors' masses until the set carries itself");
  p->add_option("--max-deflection", ps.max_deflection,
                "The table's dwell levels hold every link tip's motion relative to the table within this, m, 1e-6 .. 100 "
                "(besides the sensors' range and the links' allowables; default: no deflection limit)");
  p->add_option("--strain-span", ps.strain_span, "Place strain gauges or films this long, m, not accelerometers (EfI; spatial: each span's in- and out-of-plane faces)");
  p->add_option("--tam", ps.tam,
                "Test-analysis models on the chosen sensors, with self- and cross-orthogonality against NASA-STD-5002's "
                "criteria: guyan, irs, serep or all, comma-separated")
      ->delimiter(',');
  p->add_option("--out", ps.out,
                "Write placement.json, candidates.csv, automac.csv (tam.csv with --tam), automac.png and the review renders here");
  p->add_flag("--force", ps.force, "Replace files of the same names in --out");
  return p;
}

/// `mmvlab render` and its options.
CLI::App* addRenderCommand(CLI::App& app, RenderArgs& r) {
  CLI::App* c = app.add_subcommand("render", "Off-screen frames: the article with its sensors, a mode, a contact sheet, a mode's cycle, a time run");
  addSceneOptions(c, r);
  c->add_option("--view", r.view, "front, side, top, iso (framing the article), lab (the whole room of a scene with lab:), sensor:NAME (close up on a scene sensor), or a view the scene names (views:); default: front (iso for model: spatial, which leaves the plane the front view looks along)");
  c->add_option("--mode", r.mode, "A mode (K) or a range (K1-K2: a contact sheet); none: the static equilibrium");
  c->add_option("--scale", r.scale, "Drawing metres per unit modal coordinate (default: the largest translation 10 % of the article)")
      ->check(positive());
  c->add_option("--size", r.size, "WIDTHxHEIGHT in pixels")->capture_default_str();
  c->add_option("--history", r.history, "A `mmvlab simulate --out` directory: draw the run (video, or a still --at a time)");
  c->add_option("--fps", r.fps, "History videos and .pvd: frames per second (of video; of run time for a .pvd at --speed 1)")->check(CLI::Range(1.0, 240.0))->capture_default_str();
  c->add_option("--speed", r.speed, "History videos: run seconds per video second (0.25: slow motion)")
      ->check(CLI::Range(1e-3, 1e3))->capture_default_str();
  c->add_option("--at", r.at, "History stills (.png): the run time in s (default: the run's end)")->check(positive(true));
  c->add_option("--traces", r.traces, "History: comma-separated sensors or history.csv columns drawn in an inset")->delimiter(',');
  c->add_option("--out", r.out, "The file: .png (a frame or a contact sheet), .mp4 or .avi (a mode's cycle or a run), or .pvd with --history (the run's frames for ParaView, in FILE_frames/ beside it)")->required();
  c->add_flag("--force", r.force, "Replace the file if it exists");
  return c;
}

/// `mmvlab correlate` and its options.
CLI::App* addCorrelateCommand(CLI::App& app, CorrelateArgs& co) {
  CLI::App* c = app.add_subcommand(
      "correlate", "A measured modal test (UFF FRFs and mode shapes) against the model: pairing, MAC, FRAC, frequency errors");
  addSceneOptions(c, co);
  c->add_option("--measured", co.measured, "The measured UFF file (datasets 15/2411 nodes, 55 modes, 58 functions, 164 units)")
      ->required();
  c->add_flag("--json", co.json, "Print JSON instead of tables");
  c->add_option("--tam", co.tam,
                "FILE[:guyan|irs|serep]: a TAM written by place-sensors --tam --out (tam.mat): the measured modes' test "
                "orthogonality under its mass at its channels (the nodes of place-sensors' test geometry)");
  c->add_option("--pair-distance", co.pair_distance, "A measured node farther than this from the article is not paired, 1e-6 .. 100 m")
      ->capture_default_str();
  c->add_option("--pair", co.pairs, "NODE=POINT: pair a node with a point or station by name (repeatable)");
  c->add_option("--modes", co.modes, "Model modes compared, 1 .. 500")->capture_default_str();
  c->add_option("--mac-threshold", co.mac_threshold, "A test and a model mode pair only at or above this MAC, 0 .. 1")
      ->capture_default_str();
  c->add_option("--max-frequency-error", co.max_frequency_error,
                "A test and a model mode pair only within this relative frequency difference, |f_model / f_test - 1|, 1e-6 .. 100")
      ->capture_default_str();
  c->add_option("--damping", co.damping_ratio, "Modal damping ratio of every mode, 0 .. 1 (default: the scene's damping, else 0.01)")
      ->capture_default_str();
  c->add_option("--out", co.out, "Also write correlation.json, mac.csv, pairs.csv, mac.png and a Bode overlay per function here");
  c->add_flag("--force", co.force, "Replace files of the same names in --out");
  return c;
}

/// `mmvlab update` and its options (the pairing ones are correlate's).
CLI::App* addUpdateCommand(CLI::App& app, UpdateArgs& u) {
  CLI::App* c = app.add_subcommand("update", "Update scene values so the model reproduces a measured modal test: fit, "
                                             "identifiability, intervals, the updated scene");
  addSceneOptions(c, u);
  c->add_option("--measured", u.measured, "An article's measured UFF file (datasets 15/2411 nodes, 55 modes); none for "
                                          "HAM-SAS, updated against the slides' measured features");
  c->add_option("--params", u.params, "KEY[:LO:HI],...: scene keys to update (numbers written in the scene file, as --set names "
                                      "them); bounds in the key's units, default half to twice the nominal")
      ->delimiter(',')->required();
  c->add_option("--frequency-sigma", u.frequency_sigma, "A frequency error's stated uncertainty, relative, 1e-6 .. 1")->capture_default_str();
  c->add_option("--mac-sigma", u.mac_sigma, "(1 - MAC)'s stated uncertainty, 1e-6 .. 1")->capture_default_str();
  c->add_flag("--no-mac", u.no_mac, "Fit the frequencies only: leave (1 - MAC) out of the residuals");
  c->add_option("--regularization", u.regularization, "Pull toward the nominal, residuals per 100 % change, 0 .. 1e6")->capture_default_str();
  c->add_option("--max-iterations", u.max_iterations, "Levenberg-Marquardt iterations, 1 .. 1000")->capture_default_str();
  c->add_option("--pair-distance", u.pair_distance, "As correlate's, 1e-6 .. 100 m")->capture_default_str();
  c->add_option("--pair", u.pairs, "NODE=POINT: pair a node with a point or station by name (repeatable)");
  c->add_option("--modes", u.modes, "Model modes compared, 1 .. 500")->capture_default_str();
  c->add_option("--mac-threshold", u.mac_threshold, "As correlate's, 0 .. 1")->capture_default_str();
  c->add_option("--max-frequency-error", u.max_frequency_error, "As correlate's, 1e-6 .. 100")->capture_default_str();
  c->add_flag("--json", u.json, "Print JSON instead of tables");
  c->add_option("--out", u.out, "Also write update.json, updated_scene.yaml, parameters.csv, pairs.csv, iterations.csv and figures here");
  c->add_flag("--force", u.force, "Replace files of the same names in --out");
  return c;
}

/// `mmvlab sweep` and `mmvlab sweep-merge`.
std::pair<CLI::App*, CLI::App*> addDesignSweepCommands(CLI::App& app, DesignSweepArgs& ds, SweepMergeArgs& sm) {
  CLI::App* s = app.add_subcommand("sweep", "Design sweep from a spec: parameters x outputs (modes tracked, check margins), in parallel, resumable, sharded");
  s->add_option("spec", ds.spec, "The sweep spec (YAML, docs/planning.md)")->required();
  s->add_option("--out", ds.out, "Results directory: sweep.csv, sweep.json, journal.csv (a rerun resumes it)")->required();
  s->add_option("--jobs", ds.jobs, "Threads, 0 .. 1024 (default 0: every core)");
  s->add_option("--shard", ds.shard, "I/N: run the I-th of N deterministic slices into OUT/shard-I-of-N (default: SLURM_ARRAY_TASK_ID/COUNT when set)");
  s->add_flag("--force", ds.force, "Start over in a directory that holds another sweep's results");
  s->add_flag("--json", ds.json, "Print the summary as JSON");
  CLI::App* m = app.add_subcommand("sweep-merge", "Join the shard directories of one sweep into the CSV an unsharded run writes");
  m->add_option("shards", sm.shards, "Shard directories (OUT/shard-I-of-N)")->required();
  m->add_option("--out", sm.out, "Directory for the merged sweep.csv")->required();
  m->add_flag("--force", sm.force, "Replace an existing merged sweep.csv");
  m->add_flag("--json", sm.json, "Print the summary as JSON (the merged CSV and the figures)");
  return {s, m};
}

/// Whether `name` is a command; if not, says so with the closest ones and the list
/// (CLI11 alone would only say that a subcommand is required).
bool knownCommand(CLI::App& app, const std::string& name) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
  if (std::find(names.begin(), names.end(), name) != names.end()) return true;
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  std::cerr << "mmvlab: unknown command '" << mmv::printable(name) << "'" << mmv::didYouMean(name, names)
            << "; commands: " << list << " (mmvlab --help)\n";
  return false;
}

/// Every verb's --out: an empty path is refused by the parser.
void refuseEmptyOutPaths(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    if (CLI::Option* o = sub->get_option_no_throw("--out"))
      o->check(CLI::Validator([](std::string& v) { return v.empty() ? std::string("empty path") : std::string(); }, "PATH"));
}

/// The options given on the command line ("--duration"): a study takes only those.
std::set<std::string> givenOptions(const CLI::App* cmd) {
  std::set<std::string> given;
  for (const CLI::Option* o : cmd->get_options())
    if (o->count() > 0) given.insert(o->get_name());
  return given;
}

/// A full disk or a closed pipe behind stdout is a failure, not a success.
int withStdoutChecked(int code) {
  std::cout.flush();
  if (!std::cout) {
    if (code != mmv::cli::kOk) return code;  // the command has said why
    std::cerr << "mmvlab: cannot write to standard output (disk full or pipe closed?)\n";
    return mmv::cli::kIoError;
  }
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mmv::cli;
  CLI::App app{"mmvlab: plan ground tests of flexible multibody test articles (MMV arm, HAM-SAS)"};
  app.set_version_flag("--version", std::string("mmvlab ") + mmv::mmvlabVersion());
  app.require_subcommand(1);

  ModesArgs modes;
  CLI::App* m = addDeclaredCommand(app, "modes", modes);
  ConvergeArgs conv;
  CLI::App* c = addDeclaredCommand(app, "converge", conv);
  CompareArgs cmp;
  CLI::App* cp = addDeclaredCommand(app, "compare", cmp);
  ConfigSweepArgs sw;
  CLI::App* sp = addDeclaredCommand(app, "sweep-config", sw);
  LinearArgs lin;
  const auto [fr, ro] = addLinearCommands(app, lin);
  SimulateArgs sim;
  CLI::App* si = addDeclaredCommand(app, "simulate", sim);
  TradeArgs tr;
  CLI::App* tp = addDeclaredCommand(app, "trade", tr);
  PlaceSensorsArgs ps;
  CLI::App* pl = addPlaceSensorsCommand(app, ps);
  RenderArgs rd;
  CLI::App* rn = addRenderCommand(app, rd);

  CheckArgs ck;
  CLI::App* ch = addDeclaredCommand(app, "check", ck);
  ch->add_flag("--report-only", ck.report_only,
               "Exit 0 even when a requirement FAILs (without it a FAIL exits 3, after the whole report is written)");
  CorrelateArgs co;
  CLI::App* cr = addCorrelateCommand(app, co);
  UpdateArgs up;
  CLI::App* ud = addUpdateCommand(app, up);
  ReportArgs rp;
  CLI::App* rpc = addReportCommand(app, rp, addSceneOptions);
  DesignSweepArgs ds;
  SweepMergeArgs sm;
  const auto [dsw, smg] = addDesignSweepCommands(app, ds, sm);

  app.add_subcommand("scene", "Print the embedded default scene (a starting point for your own)");
  refuseEmptyOutPaths(app);

  if (argc > 1 && argv[1][0] != '-' && !knownCommand(app, argv[1])) return kUsage;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return withStdoutChecked(app.exit(e) == 0 ? kOk : kUsage);  // --help, --version: delivered or 74
    // CLI11 quotes the argument as given: escaped, like every other message.
    std::cerr << "mmvlab: " << mmv::printable(e.what()) << "\nRun with --help for more information.\n";
    return kUsage;
  }
  const auto run = [&]() -> int {
    if (m->parsed()) return runModesCommand(modes);
    if (c->parsed()) return runConvergeCommand(conv);
    if (ch->parsed()) return runCheckCommand(ck);
    co.damping_given = cr->count("--damping") > 0;
    if (cr->parsed()) return runCorrelateCommand(co);
    if (ud->parsed()) return runUpdateCommand(up);
    if (dsw->parsed()) return runDesignSweepCommand(ds);
    if (smg->parsed()) return runSweepMergeCommand(sm);
    if (cp->parsed()) return runCompareCommand(cmp);
    if (sp->parsed()) return runConfigSweepCommand(sw);
    lin.damping_given = fr->count("--damping") + ro->count("--damping") > 0;
    lin.range_given = fr->count("--from") + fr->count("--to") + ro->count("--from") + ro->count("--to") > 0;
    rd.given = givenOptions(rn);
    if (si->parsed()) return runSimulateCommand(sim);
    if (tp->parsed()) return runTradeCommand(tr);
    if (pl->parsed()) return runPlaceSensorsCommand(ps);
    if (rn->parsed()) return reexecWithHugePages(argv), mmv::figures::renderCommand(rd);
    if (fr->parsed()) return runFrfCommand(lin);
    if (rpc->parsed()) return runReportCommand(rp);
    if (ro->parsed()) return runRomCommand(lin);
    return runSceneCommand();
  };
  keepFreedMemory();
  const Watchdog watchdog;
  const mmv::ProgressStage stage(app.get_subcommands().empty() ? std::string("mmvlab") : app.get_subcommands().front()->get_name());
  return withStdoutChecked(run());
}

// mmvlab check (and, below it, sweep) as a user runs them.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <sstream>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

// LD_DEBUG=files makes the dynamic loader name every object it opens, dlopen included:
// the sanity line (Simbody) shows the check sees loads at all.
TEST_F(Cli, CommandsWithoutImagesDoNotLoadTheImageStack) {
  const auto loaded = [&](const std::string& args) {
    const fs::path err = dir_ / "ld.txt";
    std::system(("LD_DEBUG=files " + std::string(MMVLAB_BINARY) + " " + args + " >/dev/null 2>" + err.string()).c_str());
    return slurp(err);
  };
  for (const std::string args : {"modes --segments 2", "check", "frf --segments 2"}) {
    const std::string l = loaded(args);
    EXPECT_NE(l.find("libSimTKsimbody"), std::string::npos) << args;
    // Nor matio and its HDF5's network stack (the .mat plugin's; before 2026-11-26 every
    // command loaded them: 49 shared libraries at start-up).
    for (const char* lib : {"libopencv", "libOSMesa", "libgdal", "libmmvlab_figures", "libmatio", "libhdf5", "libcurl", "libgnutls",
                            "libkrb5", "libmmvlab_mat"})
      EXPECT_EQ(l.find(lib), std::string::npos) << args << " loaded " << lib;
  }
  // rom writes its .mat files itself (sim/io/mat5_writer.hpp): no matio; a command that
  // reads one (correlate's --tam) loads the plugin and matio.
  const fs::path rom = dir_ / "rom";
  const std::string w = loaded("rom --segments 2 --out " + rom.string());
  EXPECT_NE(w.find("libSimTKsimbody"), std::string::npos);
  for (const char* lib : {"libmmvlab_mat", "libmatio", "libhdf5", "libmmvlab_figures"})
    EXPECT_EQ(w.find(lib), std::string::npos) << "rom loaded " << lib;
  EXPECT_TRUE(fs::exists(rom / "rom.mat"));
  const std::string m = loaded("correlate --measured " + std::string(MMVLAB_SOURCE_DIR) + "/docs/figures/correlate/measured.uff --tam " +
                               (rom / "full.mat").string());
  EXPECT_NE(m.find("libmmvlab_mat.so"), std::string::npos);
  EXPECT_NE(m.find("libmatio"), std::string::npos);
  const std::string l = loaded("render --size 160x120 --out " + (dir_ / "a.png").string());
  EXPECT_NE(l.find("libmmvlab_figures.so"), std::string::npos);
  EXPECT_NE(l.find("libopencv_core"), std::string::npos);
  EXPECT_TRUE(isPng(dir_ / "a.png"));
}

TEST_F(Cli, CheckDefaultSceneNamesTheTorquersWorstCase) {
  const Result r = run("check");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("joint1 holding torque, worst over +-45 deg"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("overall: pass (3 requirements not checked: no capacity given)"), std::string::npos) << r.out;
}

TEST_F(Cli, CheckJsonAndMarkdownCarryTheOverridesAndVerdicts) {
  const Result r = run("check " + std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml --set joints.joint1.torque_capacity=100 --json --out " + (dir_ / "ck").string());
  ASSERT_EQ(r.code, 3) << r.err;  // a FAIL exits 3, after the whole report (README's exit codes)
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["overall"], "FAIL");  // about 129 N*m needed at joint 1
  EXPECT_EQ(j["overrides"][0], "joints.joint1.torque_capacity=100");
  bool found = false;
  for (const auto& l : j["lines"])
    if (l["requirement"].get<std::string>().rfind("joint1 holding", 0) == 0) {
      found = true;
      EXPECT_EQ(l["verdict"], "FAIL");
      EXPECT_DOUBLE_EQ(l["capacity"].get<double>(), 100);
      EXPECT_LT(l["margin_pct"].get<double>(), 0);
    }
  EXPECT_TRUE(found);
  EXPECT_EQ(nlohmann::json::parse(slurp(dir_ / "ck" / "check.json")), j);
  const std::string md = slurp(dir_ / "ck" / "check.md");
  EXPECT_NE(md.find("| torquers | joint1 holding torque"), std::string::npos) << md;
  EXPECT_NE(md.find("`--set joints.joint1.torque_capacity=100`"), std::string::npos);
}

// A stress above the allowable over its factor FAILs the check: exit 3 with the report
// written in full (stdout and --out); --report-only exits 0 with the same report. The
// line's demand at the scene's angles is what `modes` reports (a closed tree is checked
// there only), and its margin rule is the factor, not --margin.
TEST_F(Cli, CheckJudgesEachLinksStressAndAFailExitsThree) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv.yaml";
  const std::string weak = " --set materials.carbon_carbon.ultimate_strength=20e6";  // link 1 needs about 25 MPa x 1.4
  const Result fail = run("check " + scene + weak + " --out " + (dir_ / "ck").string());
  EXPECT_EQ(fail.code, 3) << fail.err;
  EXPECT_NE(fail.out.find("overall: FAIL"), std::string::npos) << fail.out;
  EXPECT_TRUE(fs::exists(dir_ / "ck" / "check.json"));
  const Result report = run("check " + scene + weak + " --report-only");
  EXPECT_EQ(report.code, 0) << report.err;
  EXPECT_EQ(report.out.substr(0, report.out.rfind("(")), fail.out.substr(0, fail.out.rfind("(")));  // the wall time aside
  const auto j = nlohmann::json::parse(run("check " + scene + weak + " --json --report-only").out);
  bool judged = false;
  for (const auto& l : j["lines"])
    if (l["id"] == "stress.link1.hold") {
      judged = true;
      EXPECT_EQ(l["verdict"], "FAIL");
      EXPECT_NEAR(l["capacity"].get<double>(), 20 / 1.4, 1e-9);
    }
  EXPECT_TRUE(judged);

  const std::string closed = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-closed.yaml";
  const auto c = nlohmann::json::parse(run("check " + closed + " --json --margin 90").out);
  const auto m = nlohmann::json::parse(run("modes " + closed + " --json --no-error-estimate").out);
  int lines = 0;
  for (const auto& s : m["equilibrium"]["static_stress"]["links"]) {
    for (const auto& l : c["lines"]) {
      if (l["id"] != "stress." + s["link"].get<std::string>() + ".hold") continue;
      ++lines;
      EXPECT_NEAR(l["demand"].get<double>(), 1e-6 * s["equivalent_pa"].get<double>(), 1e-7 * l["demand"].get<double>());
      EXPECT_EQ(l["verdict"], "pass");  // MS >= 0 passes, though --margin 90 asks more
    }
  }
  EXPECT_EQ(lines, 4);
}

// A 20,000 deg/s^2 slew of joint 1 (before: a torque "EXCEEDED" and exit 0, no word of
// stress) breaks every link: check's run lines FAIL on stress before any flexible run and
// the command exits 3; simulate says when each link's allowable over its factor is first
// passed. The shipped slew's own lines pass.
TEST_F(Cli, AFastSlewFailsOnStressInCheckAndSimulate) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml --segments 2";
  const std::string fast = " --set joints.joint1.slew.max_acceleration_deg_s2=20000 --set joints.joint1.slew.max_rate_deg_s=1000";
  const auto runLines = [&](const std::string& args, int code) {
    const Result r = run("check " + scene + args + " --json");
    EXPECT_EQ(r.code, code) << r.err;
    std::map<std::string, nlohmann::json> lines;
    const auto j = nlohmann::json::parse(r.out);  // kept: a loop over a temporary's member dangles
    for (const auto& l : j["lines"])
      if (l["id"].get<std::string>().rfind("stress.", 0) == 0) lines[l["id"].get<std::string>()] = l;
    return lines;
  };
  const auto slow = runLines(" --report-only", 0), broken = runLines(fast, 3);
  for (const char* link : {"link1", "link2", "link3a", "link3b"}) {
    const std::string id = std::string("stress.") + link + ".run";
    ASSERT_TRUE(slow.count(id) && broken.count(id)) << id;
    EXPECT_EQ(slow.at(id)["verdict"], "pass") << id;
    EXPECT_EQ(broken.at(id)["verdict"], "FAIL") << id;
    EXPECT_GT(broken.at(id)["demand"].get<double>(), 5 * slow.at(id)["demand"].get<double>()) << id;
  }
  // The rigid run's root moment of link 1 is joint 1's torque (two ways of one number).
  const Result check = run("check " + scene + fast + " --report-only");
  const std::size_t torque = check.out.find("joint1 peak torque during the scene's run");
  ASSERT_NE(torque, std::string::npos) << check.out;
  const auto j = nlohmann::json::parse(run("check " + scene + fast + " --json --report-only").out);
  double tau = 0;
  for (const auto& l : j["lines"])
    if (l["id"] == "torque.joint1.run") tau = l["demand"].get<double>();
  const std::string note = broken.at("stress.link1.run")["note"].get<std::string>();
  const std::size_t at = note.find("moment ");
  ASSERT_NE(at, std::string::npos) << note;
  EXPECT_NEAR(std::abs(std::stod(note.substr(at + 7))), tau, 1e-3 * tau) << note;

  const Result sim = run("simulate " + scene + fast + " --json");
  EXPECT_EQ(sim.code, 0) << sim.err;  // a run reports; check judges
  const auto s = nlohmann::json::parse(sim.out);
  int failed = 0;
  for (const auto& l : s["stress"]) {
    EXPECT_EQ(l["verdict"], "FAIL") << l;
    EXPECT_TRUE(l["first_exceeded_s"].is_number()) << l;
    EXPECT_LT(l["first_exceeded_s"].get<double>(), l["at_s"].get<double>() + 1e-12) << l;
    EXPECT_GT(l["first_exceeded_s"].get<double>(), 0.5) << l;  // the slew starts at 0.5 s
    ++failed;
  }
  EXPECT_EQ(failed, 4);
  int warned = 0;
  for (const auto& w : s["warnings"]) warned += w.get<std::string>().find("would not survive this run") != std::string::npos;
  EXPECT_EQ(warned, 4);
}

// A slew the run does not show, whole or in part, is flagged by check and simulate
// (before: accepted silently):
// the slew scene's joint 1 moves from 0.5 to 3.07 s; its 6 s run shows it, 1.2 s a part,
// 0.4 s nothing.
TEST_F(Cli, CheckFlagsASlewThatTheRunDoesNotShow) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml --segments 2 --json --report-only";
  const auto line = [&](const std::string& set) {
    const auto j = nlohmann::json::parse(run("check " + scene + set).out);
    for (const auto& l : j["lines"])
      if (l["id"] == "slew.joint1.timing") return l;
    ADD_FAILURE() << "no slew.joint1.timing line" << set;
    return nlohmann::json();
  };
  const auto whole = line(""), part = line(" --set simulation.duration=1.2"), none = line(" --set simulation.duration=0.4");
  EXPECT_EQ(whole["verdict"], "pass");
  EXPECT_EQ(part["verdict"], "advisory");
  EXPECT_NE(part["note"].get<std::string>().find("past the run's end at 1.2 s"), std::string::npos) << part;
  EXPECT_EQ(none["verdict"], "advisory");
  EXPECT_NE(none["note"].get<std::string>().find("at or after the run's end"), std::string::npos) << none;
  EXPECT_NEAR(whole["demand"].get<double>(), part["demand"].get<double>(), 1e-12);  // the slew's end: the run's length moves none of it
  // simulate says the same of its run (--duration as the scene's key).
  const auto warnings = [&](const std::string& duration) {
    const Result r = run("simulate " + std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml --segments 2 --json --duration " + duration);
    EXPECT_EQ(r.code, 0) << r.err;
    std::string all;
    const auto j = nlohmann::json::parse(r.out);  // kept: a loop over a temporary's member dangles
    for (const auto& w : j["warnings"]) all += w.get<std::string>() + "\n";
    return all;
  };
  const std::string shown = warnings("3.5"), in_part = warnings("1.2"), never = warnings("0.4");
  EXPECT_EQ(shown.find("slew:"), std::string::npos) << shown;
  EXPECT_NE(in_part.find("joint1's slew: from 0.5 s to 3.071 s, past the run's end at 1.2 s"), std::string::npos) << in_part;
  EXPECT_NE(never.find("joint1's slew: it starts at 0.5 s, at or after the run's end at 0.4 s"), std::string::npos) << never;
}

TEST_F(Cli, CheckRefusesABadBandAndAnIsolatorAndWritesNothing) {
  Result r = run("check --band 50:0.1 --out " + (dir_ / "ck").string());
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("--band"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "ck"));
  r = run("check " + std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml");
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("HAM-SAS"), std::string::npos) << r.err;
}

/// A sweep of 120 points of the default article (modes and check): 0.5-2 s on 2 cores.
std::string killableSpec() {
  return std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/mmv.yaml\n"
         "parameters:\n"
         "  - {key: sections.link3_rod.radius, range: {from: 0.001, to: 0.003, samples: 2}}\n"
         "  - {key: links.link2.length, range: {from: 1.2, to: 1.8, samples: 2}}\n"
         "design: {type: latin_hypercube, samples: 120, seed: 9}\n"
         "outputs: [frequencies, mass, check]\n";
}

TEST_F(Cli, SweepKilledAtRandomMomentsResumesToTheSameFile) {
  const fs::path spec = write("spec.yaml", killableSpec());
  const auto t0 = std::chrono::steady_clock::now();
  Result r = run("sweep " + spec.string() + " --out " + (dir_ / "whole").string());
  ASSERT_EQ(r.code, 0) << r.err;
  // Kills fall within the uninterrupted run's own duration (it varies with the machine).
  const double whole_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string whole = slurp(dir_ / "whole" / "sweep.csv");
  EXPECT_EQ(std::count(whole.begin(), whole.end(), '\n'), 121);
  bool resumed_mid_way = false;  // some kill fell inside the sweep (else the test saw nothing)
  for (unsigned seed : {1u, 2u, 3u}) {
    const fs::path out = dir_ / ("killed" + std::to_string(seed));
    unsigned state = seed;
    // SIGKILL twice, after 20-60 % of the whole run's time (start-up is a quarter of it),
    // so that the work done before the kills rarely adds up to all of it; then finish.
    // --foreground: timeout signals the sweep alone and waits until it is gone. Without it
    // a KILL goes to timeout's whole process group, timeout included, which then cannot
    // wait: the next run could start while the killed sweep still held its lock (exit 73,
    // "in use by another sweep", seen under load).
    for (int kill = 0; kill < 2; ++kill) {
      state = state * 1103515245u + 12345u;
      const double after = whole_s * (0.2 + (state >> 16) % 400 / 1000.0);
      std::system(("timeout --foreground -s KILL " + std::to_string(after) + " " + MMVLAB_BINARY + " sweep " + spec.string() + " --out " +
                   out.string() + " >/dev/null 2>&1").c_str());
    }
    r = run("sweep " + spec.string() + " --out " + out.string() + " --json");
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["computed"].get<long>() + j["reused"].get<long>(), 120);
    resumed_mid_way = resumed_mid_way || (j["reused"].get<long>() > 0 && j["computed"].get<long>() > 0);
    EXPECT_EQ(slurp(out / "sweep.csv"), whole) << "seed " << seed;
  }
  EXPECT_TRUE(resumed_mid_way);
}

// A sweep sizes against strength: check's stress lines are columns (demand in MPa, margin).
// Link 3's S-glass rods carry mainly their own weight, M ~ r^2 and sigma = M r / I ~ 1 / r:
// thrice the radius, a third of the stress (to the 2 % their axial load and the small
// torquer they share move it).
TEST_F(Cli, SweepHasEachLinksStressToSizeAgainst) {
  const fs::path spec = write("spec.yaml", std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/mmv.yaml\nsegments: 4\n"
      "parameters:\n  - {key: sections.link3_rod.radius, values: [0.001, 0.003]}\noutputs: [check]\n");
  ASSERT_EQ(run("sweep " + spec.string() + " --out " + (dir_ / "s").string()).code, 0);
  std::istringstream csv(slurp(dir_ / "s" / "sweep.csv"));
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(csv, line);) {
    std::vector<std::string> cells;
    std::istringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  ASSERT_EQ(rows.size(), 3u);
  const auto column = [&](const std::string& name) {
    const auto at = std::find(rows[0].begin(), rows[0].end(), name);
    EXPECT_NE(at, rows[0].end()) << name;
    return static_cast<std::size_t>(at - rows[0].begin());
  };
  for (const char* link : {"link1", "link2", "link3a", "link3b"}) column(std::string("stress_") + link + "_hold_margin_pct");
  const std::size_t s3 = column("stress_link3a_hold_demand");
  EXPECT_NEAR(std::stod(rows[1][s3]) / std::stod(rows[2][s3]), 3.0, 0.06);
}

TEST_F(Cli, SweepFiguresAndTheParetoFrontComeFromTheCsvAlsoWhenMerged) {
  const fs::path spec = write("spec.yaml", std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/mmv.yaml\nsegments: 4\n"
      "set: [joints.joint1.torque_capacity=150, joints.joint2.torque_capacity=12, joints.joint3.torque_capacity=0.3]\n"
      "parameters:\n  - {key: sections.link3_rod.radius, range: {from: 0.001, to: 0.003, samples: 3}}\n"
      "  - {key: links.link3.length, values: [0.5, 0.75, 1.0]}\noutputs: [frequencies, mass, check]\nmodes: 3\n");
  ASSERT_EQ(run("sweep " + spec.string() + " --out " + (dir_ / "whole").string()).code, 0);
  for (const char* f : {"frequencies_vs_links_link3_length.png", "margins_vs_sections_link3_rod_radius.png", "pareto.png", "frequency_map.png"})
    EXPECT_TRUE(isPng(dir_ / "whole" / f)) << f;
  // No point of the sweep dominates a point of the front (higher f1, lower mass, higher worst margin).
  const auto rows = [](const std::string& text) {
    std::vector<std::vector<std::string>> out;
    std::istringstream is(text);
    std::string line;
    std::getline(is, line);
    while (std::getline(is, line)) {
      std::vector<std::string> cells;
      std::istringstream ls(line);
      std::string c;
      while (std::getline(ls, c, ',')) cells.push_back(c);
      out.push_back(cells);
    }
    return out;
  };
  const auto front = rows(slurp(dir_ / "whole" / "pareto.csv"));
  ASSERT_FALSE(front.empty());
  const std::string csv = slurp(dir_ / "whole" / "sweep.csv");
  const auto all = rows(csv);
  const std::string header = csv.substr(0, csv.find('\n')) + ",";
  const auto col = [&](const std::string& name) { return static_cast<int>(std::count(header.begin(), header.begin() + header.find(name + ","), ',')); };
  ASSERT_EQ(col("mass_kg"), 10);
  for (const auto& p : front) {
    const double f = std::stod(p[1]), m = std::stod(p[2]), g = std::stod(p[3]);
    for (const auto& q : all) {
      double worst = 1e300;
      for (const char* c : {"torque_joint1_hold_margin_pct", "torque_joint2_hold_margin_pct", "torque_joint3_hold_margin_pct"})
        worst = std::min(worst, std::stod(q[col(c)]));
      const double qf = std::stod(q[col("mode1_hz")]), qm = std::stod(q[col("mass_kg")]);
      EXPECT_FALSE(qf >= f && qm <= m && worst >= g && (qf > f || qm < m || worst > g)) << "point " << q[0] << " dominates " << p[0];
    }
  }
  for (int i = 1; i <= 2; ++i) ASSERT_EQ(run("sweep " + spec.string() + " --out " + (dir_ / "sh").string() + " --shard " + std::to_string(i) + "/2").code, 0);
  ASSERT_EQ(run("sweep-merge --out " + (dir_ / "merged").string() + " " + (dir_ / "sh" / "shard-1-of-2").string() + " " +
                (dir_ / "sh" / "shard-2-of-2").string()).code, 0);
  EXPECT_EQ(slurp(dir_ / "merged" / "sweep.csv"), slurp(dir_ / "whole" / "sweep.csv"));
  EXPECT_EQ(slurp(dir_ / "merged" / "pareto.csv"), slurp(dir_ / "whole" / "pareto.csv"));
  // The merge writes the summary a local sweep writes: the same keys in the same order,
  // the same sweep (fingerprint, columns, fields), every point computed once.
  const nlohmann::json whole = nlohmann::json::parse(slurp(dir_ / "whole" / "sweep.json"));
  const nlohmann::json merged = nlohmann::json::parse(slurp(dir_ / "merged" / "sweep.json"));
  for (const auto& [key, value] : whole.items()) EXPECT_TRUE(merged.contains(key)) << key;
  for (const char* same : {"spec", "scene", "fingerprint", "design", "points", "shard", "columns", "fields"})
    EXPECT_EQ(merged[same], whole[same]) << same;
  EXPECT_EQ(merged["computed"].get<long>() + merged["reused"].get<long>(), whole["points"].get<long>());
  EXPECT_EQ(merged["csv"], (dir_ / "merged" / "sweep.csv").string());
  EXPECT_EQ(merged["merged_from"].size(), 2u);
  // A shard that never wrote its summary is refused by name, and nothing is written.
  fs::remove(dir_ / "sh" / "shard-2-of-2" / "sweep.json");
  const Result r = run("sweep-merge --out " + (dir_ / "merged2").string() + " " + (dir_ / "sh" / "shard-1-of-2").string() +
                       " " + (dir_ / "sh" / "shard-2-of-2").string());
  EXPECT_EQ(r.code, 73) << r.err;
  EXPECT_NE(r.err.find("shard-2-of-2/sweep.json"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "merged2"));
}

/// A folder's entries, each as its kind and bytes (a link as its target), for a
/// before-and-after comparison.
std::map<std::string, std::string> listing(const fs::path& root) {
  std::map<std::string, std::string> t;
  if (!fs::exists(fs::symlink_status(root))) return t;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string rel = fs::relative(it->path(), root).string();
    const fs::file_status st = fs::symlink_status(it->path());
    t[rel] = fs::is_symlink(st) ? "link:" + fs::read_symlink(it->path()).string()
             : fs::is_directory(st) ? "<dir>"
             : fs::is_regular_file(st) ? slurp(it->path())
                                       : "<special>";
    if (fs::is_symlink(st)) it.disable_recursion_pending();
  }
  return t;
}

// The sweep under every other verb's output rule (issue 68): a user's file, folder or
// link of an output's name (sweep.csv, sweep.json, a figure, pareto.csv, journal.csv) is
// refused before any point is computed (exit 73), with or without --force, and the
// folder is left byte for byte as it was; what the sweep wrote itself (its folder's
// record lists it) a rerun replaces, with or without --force, and a file of its own the
// user edited since is the user's.
TEST_F(Cli, SweepReplacesOnlyItsOwnFilesAndRefusesBeforeComputing) {
  const fs::path spec = write("spec.yaml", std::string("scene: ") + MMVLAB_SOURCE_DIR +
                                               "/scenes/mmv.yaml\nsegments: 4\nparameters:\n"
                                               "  - {key: links.link2.length, values: [1.4, 1.6]}\noutputs: [frequencies, mass, check]\nmodes: 2\n");
  const std::string sweep = "sweep " + spec.string() + " --out ";
  // A finished sweep, and its rerun (resumed: its own files replaced, no --force needed).
  const fs::path own = dir_ / "own";
  ASSERT_EQ(run(sweep + own.string()).code, 0);
  const std::string first = slurp(own / "sweep.csv");
  ASSERT_TRUE(fs::exists(own / "frequencies_vs_links_link2_length.png"));
  EXPECT_FALSE(fs::exists(own / ".mmvlab-sweep.lock"));  // the lock goes with the run
  const Result again = run(sweep + own.string());
  EXPECT_EQ(again.code, 0) << again.err;
  EXPECT_EQ(slurp(own / "sweep.csv"), first);
  // A file of its own the user changed since is theirs: refused, kept.
  std::ofstream(own / "sweep.json", std::ios::app) << "edited\n";
  const auto edited = listing(own);
  for (const char* force : {"", " --force"}) {
    const Result r = run(sweep + own.string() + force);
    EXPECT_EQ(r.code, 73) << force << r.err;
    EXPECT_NE(r.err.find("sweep.json exists and was not written by mmvlab here"), std::string::npos) << r.err;
    EXPECT_EQ(listing(own), edited) << force;
  }
  struct Conflict {
    std::string name, kind;  // kind: file, dir, full-dir, link
  };
  const std::vector<Conflict> conflicts = {
      {"sweep.csv", "file"}, {"sweep.json", "file"}, {"pareto.csv", "file"}, {"pareto.png", "file"},
      {"frequencies_vs_links_link2_length.png", "file"}, {"sweep.csv", "link"}, {"sweep.json", "dir"},
      {"journal.csv", "file"}, {"journal.csv", "dir"}, {"journal.csv", "full-dir"}, {"journal.csv", "link"}};
  int k = 0;
  for (const Conflict& c : conflicts)
    for (const char* force : {"", " --force"}) {
      const fs::path out = dir_ / ("c" + std::to_string(k++));
      fs::create_directories(out);
      std::ofstream(dir_ / "target.txt") << "the link's target\n";
      std::ofstream(out / "notes.txt") << "mine\n";
      if (c.kind == "file") std::ofstream(out / c.name) << "the user's own " << c.name << "\n";
      if (c.kind == "dir" || c.kind == "full-dir") fs::create_directory(out / c.name);
      if (c.kind == "full-dir") std::ofstream(out / c.name / "inside.txt") << "keep\n";
      if (c.kind == "link") fs::create_symlink(dir_ / "target.txt", out / c.name);
      const auto before = listing(out);
      const std::string where = c.name + " (" + c.kind + ")" + force;
      const Result r = run(sweep + out.string() + force);
      EXPECT_EQ(r.code, 73) << where << "\n" << r.err;
      EXPECT_EQ(r.err.find("internal error"), std::string::npos) << where << "\n" << r.err;
      EXPECT_NE(r.err.find(c.name), std::string::npos) << where << "\n" << r.err;
      EXPECT_EQ(listing(out), before) << where;
      EXPECT_EQ(slurp(dir_ / "target.txt"), "the link's target\n") << where;
    }
}

TEST_F(Cli, BadSweepSpecsExit65AndWriteNothing) {
  const std::string scene = std::string("scene: ") + MMVLAB_SOURCE_DIR + "/scenes/mmv.yaml\n";
  const std::pair<std::string, std::string> cases[] = {
      {"parameters:\n  - {key: links.link7.length, values: [1]}\noutputs: [mass]\n", "no item 'link7'"},
      {"parameters:\n  - {key: links.link1.length, range: {from: 3, to: 2, samples: 4}}\noutputs: [mass]\n", "above"},
      {"parameters:\n  - {key: links.link1.length, range: {from: 2, to: 2, samples: 4}}\noutputs: [mass]\n", "empty"},
      {"parameters:\n  - {key: links.link1.length, range: {from: 2, to: 3, samples: 0}}\noutputs: [mass]\n", "samples"},
      {"parameters:\n  - {key: links.link1.length, values: [2]}\noutputs: [frequency]\n", "unknown output"},
  };
  for (const auto& [body, what] : cases) {
    const fs::path spec = write("bad.yaml", scene + body);
    const Result r = run("sweep " + spec.string() + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.code, 65) << body << r.err;
    EXPECT_NE(r.err.find(spec.string() + ":"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << body;
  }
  EXPECT_EQ(run("sweep " + write("ok.yaml", scene + "parameters:\n  - {key: links.link1.length, values: [2]}\noutputs: [mass]\n").string() +
                " --out " + (dir_ / "out").string() + " --shard 4/3").code, 64);
}

}  // namespace
}  // namespace mmv::cli_testing

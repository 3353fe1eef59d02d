// mmvlab sweep-config: system modes and synthesis error over a grid of joint angles.
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

#include "renders/plot.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/sweep.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {
namespace {

GridAxis parseGrid(const std::string& text, const ArticleScene& scene) {
  // JOINT:FROM:TO:STEP, angles in degrees.
  std::vector<std::string> parts;
  std::stringstream ss(text);
  for (std::string p; std::getline(ss, p, ':');) parts.push_back(p);
  const std::string form = "--grid " + text + ": expected JOINT:FROM_DEG:TO_DEG:STEP_DEG, e.g. joint2:-45:45:5";
  if (parts.size() != 4) throw UsageError(form);
  GridAxis ax;
  ax.joint = parts[0];
  if (!scene.article.findJoint(ax.joint)) {
    std::string known;
    for (const auto& j : scene.article.joints) known += (known.empty() ? "" : ", ") + j.name;
    throw UsageError("--grid " + text + ": unknown joint '" + ax.joint + "' (known: " + known + ")");
  }
  double* v[3] = {&ax.from_deg, &ax.to_deg, &ax.step_deg};
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    *v[i] = std::strtod(parts[i + 1].c_str(), &end);
    if (parts[i + 1].empty() || *end != '\0' || !std::isfinite(*v[i])) throw UsageError(form);
  }
  if (!(ax.step_deg > 0) || ax.to_deg < ax.from_deg) throw UsageError("--grid " + text + ": need FROM <= TO and STEP > 0");
  if (ax.values().size() > 2000) throw UsageError("--grid " + text + ": more than 2000 values on one axis");
  return ax;
}

std::string csv(const SweepResult& r) {
  std::ostringstream os;
  for (const auto& ax : r.axes) os << ax.joint << "_deg,";
  os << "track,sorted_mode,frequency_hz,mac_to_previous,synthesized_frequency_hz,synthesis_relative_error,"
        "synthesis_mac,verdict,strain_link\n";
  for (const auto& p : r.points) {
    if (!p.solved) {  // one row saying why there is nothing
      for (double a : p.angles_deg) os << strf("%g,", a);
      os << ",,,,,,,\"no equilibrium: " << p.failure << "\",\n";
    }
    for (std::size_t k = 0; k < p.tracks.size(); ++k) {
      const TrackPoint& t = p.tracks[k];
      for (double a : p.angles_deg) os << strf("%g,", a);
      os << k + 1 << ',' << t.sorted_mode << ',' << (t.stable ? strf("%.8g", t.frequency_hz) : "") << ','
         << strf("%.6f,%.8g,%.6g,%.6f", t.mac_to_previous, t.synth_hz, t.synth_error, t.synth_mac) << ',' << t.verdict
         << ',' << t.strain_link << '\n';
    }
  }
  return os.str();
}

std::string text(const SweepResult& r) {
  std::ostringstream os;
  os << "Configuration map: system modes tracked by shape (MAC); in parentheses the synthesis error\n"
     << "of " << r.synthesis_method << " (%; * = not 'predicted': MAC < 0.9 or |err| > 1 %)\n\n";
  std::vector<std::string> head;
  for (const auto& ax : r.axes) head.push_back(ax.joint + "_deg");
  std::size_t tracks = 0;
  for (const auto& p : r.points) tracks = std::max(tracks, p.tracks.size());
  for (std::size_t k = 0; k < tracks; ++k) head.push_back(strf("track%zu_Hz (err_%%)", k + 1));
  Table t(head);
  for (const auto& p : r.points) {
    std::vector<std::string> row;
    for (double a : p.angles_deg) row.push_back(strf("%g", a));
    if (!p.solved) row.push_back("no equilibrium (see below)");
    for (const auto& tp : p.tracks)
      row.push_back(tp.stable ? strf("%.4f (%+.2f)%s", tp.frequency_hz, 100 * tp.synth_error, tp.verdict == "predicted" ? " " : "*")
                              : std::string("UNSTABLE"));
    t.add(row);
  }
  os << t.text();
  // Where does each track stop being predicted?
  os << "\nPer track: worst synthesis error, and the grid points where the synthesis does not predict it\n";
  Table s({"track", "strain link at start", "max |err|_%", "points not predicted", "points unstable"});
  for (std::size_t k = 0; k < tracks; ++k) {
    double worst = 0;
    int bad = 0, solved = 0, unstable = 0;
    std::string start;
    for (const auto& p : r.points) {
      if (k >= p.tracks.size()) continue;
      if (start.empty()) start = p.tracks[k].strain_link;
      if (!p.tracks[k].stable) {  // an error in a growth rate is not a frequency error
        ++unstable;
        continue;
      }
      ++solved;
      worst = std::max(worst, std::abs(p.tracks[k].synth_error));
      bad += p.tracks[k].verdict != "predicted";
    }
    s.add({strf("%zu", k + 1), start, strf("%.2f", 100 * worst), strf("%d of %d", bad, solved), strf("%d", unstable)});
  }
  os << s.text();
  if (r.failed_points > 0) {
    os << strf("\n%d grid point%s without a result:\n", r.failed_points, r.failed_points > 1 ? "s" : "");
    for (const auto& p : r.points) {
      if (p.solved) continue;
      os << " ";
      for (std::size_t a = 0; a < p.angles_deg.size(); ++a) os << ' ' << r.axes[a].joint << ' ' << strf("%g", p.angles_deg[a]) << " deg";
      os << ": " << p.failure << '\n';
    }
  }
  os << strf("\nTracking: worst MAC between consecutive points %.3f%s\n", r.min_tracking_mac,
             r.min_tracking_mac < 0.8 ? " (low: refine the grid step to follow the shapes)" : "");
  return os.str();
}

nlohmann::ordered_json json(const SweepResult& r) {
  nlohmann::ordered_json j;
  j["mmvlab_version"] = mmvlabVersion();
  j["command"] = "sweep-config";
  auto axes = nlohmann::ordered_json::array();
  for (const auto& ax : r.axes)
    axes.push_back({{"joint", ax.joint}, {"from_deg", ax.from_deg}, {"to_deg", ax.to_deg}, {"step_deg", ax.step_deg}});
  j["axes"] = axes;
  j["synthesis_method"] = r.synthesis_method;
  j["min_tracking_mac"] = r.min_tracking_mac;
  j["failed_points"] = r.failed_points;
  auto pts = nlohmann::ordered_json::array();
  for (const auto& p : r.points) {
    auto tr = nlohmann::ordered_json::array();
    for (const auto& t : p.tracks)
      tr.push_back({{"sorted_mode", t.sorted_mode},
                    {"frequency_hz", t.stable ? nlohmann::ordered_json(t.frequency_hz) : nlohmann::ordered_json(nullptr)},
                    {"mac_to_previous", t.mac_to_previous},
                    {"synthesized_frequency_hz", t.synth_hz},
                    {"synthesis_relative_error", t.synth_error},
                    {"synthesis_mac", t.synth_mac},
                    {"verdict", t.verdict},
                    {"strain_link", t.strain_link}});
    nlohmann::ordered_json pj = {{"angles_deg", p.angles_deg}, {"solved", p.solved}, {"tracks", tr}};
    if (!p.solved) pj["failure"] = p.failure;
    pts.push_back(pj);
  }
  j["points"] = pts;
  return j;
}

void plots(OutputDir& out, const SweepResult& r) {
  std::size_t tracks = 0;
  for (const auto& p : r.points) tracks = std::max(tracks, p.tracks.size());
  try {
    if (r.axes.size() == 1) {
      std::vector<render::Series> freq, err;
      for (std::size_t k = 0; k < tracks; ++k) {
        render::Series f{strf("track %zu", k + 1)}, s{strf("track %zu synth.", k + 1)}, e{strf("track %zu", k + 1)};
        s.dashed = true;
        for (const auto& p : r.points) {
          if (k >= p.tracks.size()) {  // a gap in the line
            for (auto* series : {&f, &s, &e}) {
              series->x.push_back(p.angles_deg[0]);
              series->y.push_back(NAN);
            }
            continue;
          }
          const auto& t = p.tracks[k];
          f.x.push_back(p.angles_deg[0]);
          f.y.push_back(t.stable ? t.frequency_hz : NAN);
          s.x.push_back(p.angles_deg[0]);
          s.y.push_back(t.stable ? t.synth_hz : NAN);
          e.x.push_back(p.angles_deg[0]);
          e.y.push_back(t.stable ? 100 * std::abs(t.synth_error) : NAN);
        }
        freq.push_back(f);
        err.push_back(e);
      }
      render::writeLinePlotPng(out.stage("frequencies.png"), freq, "System modes tracked by shape",
                               r.axes[0].joint + " angle (deg)", "frequency (Hz)", true);
      render::writeLinePlotPng(out.stage("synthesis_error.png"), err, "Synthesis error: " + r.synthesis_method,
                               r.axes[0].joint + " angle (deg)", "|synthesized / full - 1| (%)", false);
    } else {
      const auto a0 = r.axes[0].values(), a1 = r.axes[1].values();
      Eigen::MatrixXd worst = Eigen::MatrixXd::Zero(a1.size(), a0.size());
      for (const auto& p : r.points) {
        int i = 0, j = 0;
        for (std::size_t x = 0; x < a0.size(); ++x)
          if (std::abs(a0[x] - p.angles_deg[0]) < 1e-9) i = static_cast<int>(x);
        for (std::size_t y = 0; y < a1.size(); ++y)
          if (std::abs(a1[y] - p.angles_deg[1]) < 1e-9) j = static_cast<int>(y);
        for (const auto& t : p.tracks) worst(j, i) = std::max(worst(j, i), 100 * std::abs(t.synth_error));
      }
      std::vector<std::string> rows, cols;
      for (double v : a1) rows.push_back(strf("%g", v));
      for (double v : a0) cols.push_back(strf("%g", v));
      render::writeHeatmapPng(out.stage("synthesis_error.png"), worst, rows, cols,
                              "Worst synthesis error over the tracked modes (%)", r.axes[1].joint + " (deg)",
                              r.axes[0].joint + " (deg)", 0.0, std::max(worst.maxCoeff(), 1e-3));
    }
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runSweepCommand(const SweepArgs& args) {
  return guarded([&] {
    const ArticleScene scene = loadArticleScene(args, "sweep-config");
    SweepOptions o;
    if (args.grids.empty() || args.grids.size() > 2) throw UsageError("--grid: give one or two grids");
    for (const auto& g : args.grids) o.axes.push_back(parseGrid(g, scene));
    if (o.axes.size() == 2 && o.axes[0].joint == o.axes[1].joint) throw UsageError("--grid: the two grids name the same joint");
    o.modes = args.modes;
    parseComponentArgs(args.bc, args.tip_mass, o.synthesis.component);
    if (args.method == "assumed") o.synthesis.method = CmsMethod::AssumedModes;
    else if (args.method == "craig-bampton") o.synthesis.method = CmsMethod::CraigBampton;
    else throw UsageError("--method: unknown method '" + args.method + "' (known: assumed, craig-bampton)");
    o.synthesis.modes_per_link = args.component_modes;
    std::unique_ptr<OutputDir> out;
    if (!args.out.empty()) out = std::make_unique<OutputDir>(args.out, args.force);
    const SweepResult r = runSweep(scene, o);
    if (out) {
      std::ofstream(out->stage("sweep.csv"), std::ios::binary) << csv(r);
      std::ofstream(out->stage("sweep.json"), std::ios::binary) << json(r).dump(2) << '\n';
      plots(*out, r);
      for (const auto& path : out->commit()) std::cerr << "mmvlab: wrote " << path << '\n';
    }
    std::cout << (args.json ? json(r).dump(2) + "\n" : text(r)) << std::flush;
    return kOk;
  });
}

}  // namespace mmv::cli

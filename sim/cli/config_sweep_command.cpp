// mmvlab sweep-config: system modes and synthesis error over a grid of joint angles.
#include <cmath>
#include <fstream>
#include <iostream>
#include <optional>

#include "sim/app/config_sweep_study.hpp"
#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/modes/config_sweep.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {
namespace {

/// A 1-D sweep's figures: the tracked modes' frequencies (log: they span decades), each
/// mode's change from its first value (linear, so a few per cent show), and the
/// synthesis error. Unstable shapes are rings at |f| (the growth rate / 2 pi).
void lineSweepPlots(OutputDir& out, const ConfigSweepResult& r, std::size_t tracks, const std::string& scene_name,
                    std::optional<double> nominal_deg) {
  std::vector<render::Series> freq, change, err;
  render::Series unstable{"unstable (ring at growth rate / 2 pi)", {}, {}};
  unstable.markers_only = true;
  unstable.hollow = true;
  unstable.colour_index = 0;
  for (std::size_t k = 0; k < tracks; ++k) {
    std::string link;
    double f0 = NAN;
    for (const auto& p : r.points)
      if (k < p.tracks.size() && p.tracks[k].stable && std::isnan(f0)) f0 = p.tracks[k].frequency_hz, link = p.tracks[k].strain_link;
    const std::string label = strf("mode %zu (%s, %.3g Hz at %g deg)", k + 1, link.empty() ? "-" : link.c_str(), f0,
                                   r.points.front().angles_deg[0]);
    render::Series f{label, {}, {}}, c{label, {}, {}}, e{label, {}, {}};
    for (auto* series : {&f, &c, &e}) series->colour_index = static_cast<int>(k % 13) + 1;  // a mode keeps its colour
    for (const auto& p : r.points) {
      const double x = p.angles_deg[0];
      if (k >= p.tracks.size()) {  // a gap in the line
        for (auto* series : {&f, &c, &e}) series->x.push_back(x), series->y.push_back(NAN);
        continue;
      }
      const auto& t = p.tracks[k];
      if (t.state.rfind("lost", 0) == 0 || t.state.rfind("restarted", 0) == 0)  // another mode from here: break the line
        for (auto* series : {&f, &c, &e}) series->x.push_back(x), series->y.push_back(NAN);
      if (!t.stable) unstable.x.push_back(x), unstable.y.push_back(std::abs(t.frequency_hz));
      f.x.push_back(x);
      f.y.push_back(t.stable ? t.frequency_hz : NAN);
      c.x.push_back(x);
      c.y.push_back(t.stable ? 100 * (t.frequency_hz / f0 - 1) : NAN);
      e.x.push_back(x);
      e.y.push_back(t.stable ? 100 * std::abs(t.synth_error) : NAN);
    }
    freq.push_back(f);
    change.push_back(c);
    err.push_back(e);
  }
  if (!unstable.x.empty()) freq.push_back(unstable);
  // The scene's own angle, where the other commands' numbers are: a vertical line over
  // each figure's values (the frequency figure's, a log axis, only where positive).
  if (nominal_deg) {
    for (auto* fig : {&freq, &change, &err}) {
      double lo = INFINITY, hi = -INFINITY;
      for (const auto& s : *fig)
        for (double y : s.y)
          if (std::isfinite(y) && (fig != &freq || y > 0)) lo = std::min(lo, y), hi = std::max(hi, y);
      if (!std::isfinite(lo)) continue;
      render::Series at{strf("the scene's angle (%g deg)", *nominal_deg), {*nominal_deg, *nominal_deg}, {lo, hi}};
      at.dashed = true;
      at.colour_index = 13;  // grey: not a mode's colour
      fig->push_back(at);
    }
  }
  const std::string axis = r.axes[0].joint + " angle (deg)";
  figures::linePlot(out.stage("frequencies.png"), freq, "System modes tracked by shape: " + scene_name, axis,
                    "frequency (Hz)", true);
  figures::linePlot(out.stage("frequency_change.png"), change,
                    "Each mode's frequency against its value at the first angle: " + scene_name, axis,
                    "change from the first angle (%)", false);
  figures::linePlot(out.stage("synthesis_error.png"), err, "Synthesis error (" + r.synthesis_method + "): " + scene_name,
                    axis, "|synthesized / full - 1| (%)", false);
}

void plots(OutputDir& out, const ConfigSweepResult& r, const std::string& scene_name, std::optional<double> nominal_deg) {
  std::size_t tracks = 0;
  for (const auto& p : r.points) tracks = std::max(tracks, p.tracks.size());
  try {
    if (r.axes.size() == 1) {
      lineSweepPlots(out, r, tracks, scene_name, nominal_deg);
    } else {
      const auto a0 = r.axes[0].values(), a1 = r.axes[1].values();
      Eigen::MatrixXd worst = Eigen::MatrixXd::Zero(a1.size(), a0.size());
      for (const auto& p : r.points) {
        if (p.refined) continue;  // the map shows the grid
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
      figures::heatmap(out.stage("synthesis_error.png"), worst, rows, cols,
                              "Worst synthesis error over the tracked modes (%): " + scene_name, r.axes[1].joint + " (deg)",
                              r.axes[0].joint + " (deg)", 0.0, std::max(worst.maxCoeff(), 1e-3));
    }
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace

int runConfigSweepCommand(const ConfigSweepArgs& args) {
  return guarded([&] {
    const Scene scene = loadScene(args);
    const auto r = declaredRequest<app::ConfigSweepRequest>(args);
    std::optional<OutputDir> out;  // lives until stdout has the result: a failure there puts --out back
    if (!args.out.empty()) out.emplace(args.out, args.force);  // a bad --out refused before the work
    const app::ConfigSweepStudy s = app::runConfigSweepStudy(scene, r);
    if (out) {
      out->write("sweep.csv", s.csv);
      out->write("sweep.json", s.json.dump(2) + "\n");
      std::optional<double> nominal;  // the swept joint's angle in the scene
      if (const auto* a = std::get_if<ArticleScene>(&scene); a && !s.result.axes.empty())
        for (const auto& j : a->article.joints)
          if (j.name == s.result.axes[0].joint) nominal = j.angle * 180 / M_PI;
      plots(*out, s.result, sceneName(scene), nominal);
      out->commit();  // reported as written when the command succeeds
    }
    args.json ? emitResult(s.json) : emitResult(s.text);
    return kOk;
  });
}

}  // namespace mmv::cli

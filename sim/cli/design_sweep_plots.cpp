// The figures of `mmvlab sweep` and `sweep-merge`, drawn from sweep.csv itself (so a
// merged file gets the same figures as an unsharded run): frequency and margins
// against each parameter, the Pareto front of lowest frequency against mass and worst
// torque margin, and a 2-D grid's map of the first frequency.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

#include "sim/cli/figures.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/scene/key_units.hpp"

namespace mmv::cli {
namespace {

namespace fs = std::filesystem;

struct SweepTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> parameters;  ///< the columns between point and status.
  int column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    return it == header.end() ? -1 : static_cast<int>(it - header.begin());
  }
  double number(std::size_t row, int col) const {
    if (col < 0 || rows[row][col].empty()) return NAN;
    return std::strtod(rows[row][col].c_str(), nullptr);
  }
};

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream is(line);
  std::string cell;
  while (std::getline(is, cell, ',')) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

SweepTable readTable(const std::string& csv_text) {
  std::istringstream in(csv_text);
  SweepTable t;
  std::string line;
  std::getline(in, line);
  t.header = splitCsv(line);
  while (std::getline(in, line)) t.rows.push_back(splitCsv(line));
  for (std::size_t c = 1; c < t.header.size() && t.header[c] != "status"; ++c) t.parameters.push_back(t.header[c]);
  return t;
}

/// The columns ending in `suffix` (mode<k>_hz; torque_*_margin_pct).
std::vector<int> columnsLike(const SweepTable& t, const std::string& prefix, const std::string& suffix) {
  std::vector<int> out;
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    const std::string& h = t.header[c];
    if (h.size() > suffix.size() && h.rfind(prefix, 0) == 0 && h.compare(h.size() - suffix.size(), suffix.size(), suffix) == 0)
      out.push_back(static_cast<int>(c));
  }
  return out;
}

/// The margin axis' extent, %: a margin beyond it is drawn at its edge as a ring.
constexpr double kMarginAxis = 100;

/// y columns against parameter p: lines for a one-parameter sweep, points otherwise.
void againstParameter(const SweepTable& t, const fs::path& path, int p, const std::vector<int>& ys, const std::string& title,
                      const std::string& y_label, bool margins = false) {
  std::vector<render::Series> series;
  std::vector<std::size_t> order(t.rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.number(a, p) < t.number(b, p); });
  bool clipped = false;
  for (std::size_t k = 0; k < ys.size(); ++k) {
    const int c = ys[k];
    render::Series s{t.header[c], {}, {}}, beyond{"", {}, {}};
    s.markers_only = t.parameters.size() > 1;
    beyond.markers_only = beyond.hollow = true;
    // Margins beyond +-100 % (a pair of modes 1000 % closer than their bandwidth allows)
    // are rings at the axis' edge, so the margins that matter keep the scale.
    if (margins) s.colour_index = beyond.colour_index = static_cast<int>(k % 12) + 1;  // 0 and 13: the reference lines
    for (std::size_t i : order) {
      const double x = t.number(i, p), y = t.number(i, c);
      if (margins && std::abs(y) > kMarginAxis) {
        beyond.x.push_back(x), beyond.y.push_back(std::copysign(kMarginAxis, y));
        s.x.push_back(x), s.y.push_back(NAN);
        continue;
      }
      s.x.push_back(x);
      s.y.push_back(y);
    }
    series.push_back(s);
    if (!beyond.x.empty()) series.push_back(beyond), clipped = true;
  }
  if (margins) {  // where a margin runs out, and the margin check asks for (its default)
    const double x0 = t.number(order.front(), p), x1 = t.number(order.back(), p);
    for (const auto& [level, label] : {std::pair<double, const char*>{0.0, "0 % (at capacity)"}, {20.0, "20 % (check's required margin)"}}) {
      render::Series l{label, {x0, x1}, {level, level}};
      l.dashed = true;
      l.colour_index = level == 0 ? 0 : 13;  // black, grey
      series.push_back(l);
    }
  }
  figures::linePlot(path.string(), series, clipped ? title + " (rings: beyond +-100 %, drawn at the edge)" : title,
                    sceneKeyLabel(t.header[p]), y_label);
}

/// Points not dominated in (higher first frequency, lower mass, higher worst torque margin).
std::vector<std::size_t> paretoFront(const std::vector<std::array<double, 3>>& v) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i][0]) || !std::isfinite(v[i][1]) || !std::isfinite(v[i][2])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < v.size() && !dominated; ++j)
      dominated = j != i && v[j][0] >= v[i][0] && v[j][1] <= v[i][1] && v[j][2] >= v[i][2] &&
                  (v[j][0] > v[i][0] || v[j][1] < v[i][1] || v[j][2] > v[i][2]);
    if (!dominated) front.push_back(i);
  }
  return front;
}

void pareto(const SweepTable& t, OutputDir& out) {
  const int f1 = t.column("mode1_hz"), mass = t.column("mass_kg");
  const std::vector<int> margins = columnsLike(t, "torque_", "_margin_pct");  // check line ids as CSV names
  if (f1 < 0 || mass < 0 || margins.empty()) return;
  std::vector<std::array<double, 3>> v;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    double worst = INFINITY;
    for (int c : margins) worst = std::min(worst, t.number(i, c));
    v.push_back({t.number(i, f1), t.number(i, mass), worst});
  }
  const auto front = paretoFront(v);
  std::string csv = "point,mode1_hz,mass_kg,worst_torque_margin_pct\n";
  render::Series all{"every point", {}, {}}, feasible{"torque margins >= 0", {}, {}}, best{"Pareto front (f1, mass, margin)", {}, {}};
  all.markers_only = feasible.markers_only = best.markers_only = true;
  for (std::size_t i = 0; i < v.size(); ++i) {
    all.x.push_back(v[i][1]), all.y.push_back(v[i][0]);
    if (v[i][2] >= 0) feasible.x.push_back(v[i][1]), feasible.y.push_back(v[i][0]);
  }
  for (std::size_t i : front) {
    best.x.push_back(v[i][1]), best.y.push_back(v[i][0]);
    csv += t.rows[i][0] + strf(",%.10g,%.10g,%.6g\n", v[i][0], v[i][1], v[i][2]);
  }
  out.write("pareto.csv", csv);
  // No feasible point: said in the title, not as a legend entry with nothing drawn.
  std::vector<render::Series> drawn{all};
  if (!feasible.x.empty()) drawn.push_back(feasible);
  drawn.push_back(best);
  figures::linePlot(out.stage("pareto.png"), drawn,
                    std::string("Lowest frequency against mass (worst torque margin the third objective)") +
                        (feasible.x.empty() ? "; no point has every torque margin >= 0" : ""),
                    "mass (kg)", "mode 1 (Hz)");
}

/// The frequency column that varies most over the sweep, relative to its mean (a sweep
/// of link 3's sizing moves link 3's first mode, not the article's first): a link's
/// first mode (`first_mode:LINK` outputs, which follow one shape) before the ranked
/// modes, whose order changes where two cross. -1 if none.
int mostVaryingFrequency(const SweepTable& t, double& variation) {
  int best = -1;
  variation = 0;
  const bool followed = std::any_of(t.header.begin(), t.header.end(), [](const std::string& h) { return h.rfind("first_mode_", 0) == 0; });
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    const std::string& h = t.header[c];
    if (h.size() < 4 || h.compare(h.size() - 3, 3, "_hz") != 0 || (followed && h.rfind("first_mode_", 0) != 0)) continue;
    double lo = INFINITY, hi = -INFINITY, sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      if (const double v = t.number(i, static_cast<int>(c)); std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v), sum += v, ++n;
    if (n == 0 || !(sum > 0)) continue;
    const double v = (hi - lo) / (sum / n);
    if (best < 0 || v > variation) best = static_cast<int>(c), variation = v;
  }
  return best;
}

/// A full grid over two parameters: the frequency that varies most, its value in each cell.
void gridMap(const SweepTable& t, OutputDir& out) {
  double variation = 0;
  const int f = mostVaryingFrequency(t, variation);
  if (t.parameters.size() != 2 || f < 0) return;
  std::set<double> a, b;
  for (std::size_t i = 0; i < t.rows.size(); ++i) a.insert(t.number(i, 1)), b.insert(t.number(i, 2));
  if (a.size() * b.size() != t.rows.size() || a.size() > 40 || b.size() > 40) return;  // not a full grid (a Latin hypercube)
  const std::vector<double> av(a.begin(), a.end()), bv(b.begin(), b.end());
  Eigen::MatrixXd m(av.size(), bv.size());
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    m(std::find(av.begin(), av.end(), t.number(i, 1)) - av.begin(), std::find(bv.begin(), bv.end(), t.number(i, 2)) - bv.begin()) = t.number(i, f);
  std::vector<std::string> al, bl;
  for (double x : av) al.push_back(strf("%.4g", x));
  for (double x : bv) bl.push_back(strf("%.4g", x));
  double lo = INFINITY, hi = -INFINITY;  // over the cells that hold a number (a missing one is drawn "n/a")
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (std::isfinite(m(i))) lo = std::min(lo, m(i)), hi = std::max(hi, m(i));
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  figures::heatmap(out.stage("frequency_map.png"), m, al, bl,
                   strf("%s (Hz) over the grid: the frequency that varies most (%.0f %% of its mean)", t.header[f].c_str(), 100 * variation),
                   sceneKeyLabel(t.header[1]), sceneKeyLabel(t.header[2]), lo, hi > lo ? hi : lo + 1);
}

}  // namespace

void writeDesignSweepPlots(const std::string& csv_text, OutputDir& out) {
  const SweepTable t = readTable(csv_text);
  if (t.rows.empty()) return;
  const std::vector<int> freqs = columnsLike(t, "mode", "_hz"), margins = columnsLike(t, "", "_margin_pct");
  for (std::size_t k = 0; k < t.parameters.size(); ++k) {
    const int p = static_cast<int>(k) + 1;
    if (!freqs.empty())
      againstParameter(t, out.stage("frequencies_vs_" + fileNameSafe(t.parameters[k]) + ".png"), p, freqs,
                       "Tracked modes against " + t.parameters[k], "frequency (Hz)");
    if (!margins.empty())
      againstParameter(t, out.stage("margins_vs_" + fileNameSafe(t.parameters[k]) + ".png"), p, margins,
                       "Check margins against " + t.parameters[k], "margin (%)", true);
  }
  pareto(t, out);
  gridMap(t, out);
}

}  // namespace mmv::cli

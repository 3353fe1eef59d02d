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

std::string fileSafe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
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

/// y columns against parameter p: lines for a one-parameter sweep, points otherwise.
void againstParameter(const SweepTable& t, const fs::path& path, int p, const std::vector<int>& ys, const std::string& title,
                      const std::string& y_label) {
  std::vector<render::Series> series;
  std::vector<std::size_t> order(t.rows.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.number(a, p) < t.number(b, p); });
  for (int c : ys) {
    render::Series s{t.header[c], {}, {}};
    s.markers_only = t.parameters.size() > 1;
    for (std::size_t i : order) {
      s.x.push_back(t.number(i, p));
      s.y.push_back(t.number(i, c));
    }
    series.push_back(s);
  }
  figures::linePlot(path.string(), series, title, t.header[p], y_label);
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
  figures::linePlot(out.stage("pareto.png"), {all, feasible, best}, "Lowest frequency against mass (worst torque margin the third objective)",
                           "mass (kg)", "mode 1 (Hz)");
}

/// A full grid over two parameters: the first frequency on the grid, value in each cell.
void gridMap(const SweepTable& t, OutputDir& out) {
  const int f1 = t.column("mode1_hz");
  if (t.parameters.size() != 2 || f1 < 0) return;
  std::set<double> a, b;
  for (std::size_t i = 0; i < t.rows.size(); ++i) a.insert(t.number(i, 1)), b.insert(t.number(i, 2));
  if (a.size() * b.size() != t.rows.size() || a.size() > 40 || b.size() > 40) return;  // not a full grid (a Latin hypercube)
  const std::vector<double> av(a.begin(), a.end()), bv(b.begin(), b.end());
  Eigen::MatrixXd m(av.size(), bv.size());
  for (std::size_t i = 0; i < t.rows.size(); ++i)
    m(std::find(av.begin(), av.end(), t.number(i, 1)) - av.begin(), std::find(bv.begin(), bv.end(), t.number(i, 2)) - bv.begin()) = t.number(i, f1);
  std::vector<std::string> al, bl;
  for (double x : av) al.push_back(strf("%.4g", x));
  for (double x : bv) bl.push_back(strf("%.4g", x));
  double lo = INFINITY, hi = -INFINITY;  // over the cells that hold a number (a missing one is drawn "n/a")
  for (Eigen::Index i = 0; i < m.size(); ++i)
    if (std::isfinite(m(i))) lo = std::min(lo, m(i)), hi = std::max(hi, m(i));
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  figures::heatmap(out.stage("mode1_map.png"), m, al, bl, "Mode 1 (Hz) over the grid", t.header[1], t.header[2], lo,
                          hi > lo ? hi : lo + 1);
}

}  // namespace

void writeDesignSweepPlots(const std::string& csv_text, OutputDir& out) {
  const SweepTable t = readTable(csv_text);
  if (t.rows.empty()) return;
  const std::vector<int> freqs = columnsLike(t, "mode", "_hz"), margins = columnsLike(t, "", "_margin_pct");
  for (std::size_t k = 0; k < t.parameters.size(); ++k) {
    const int p = static_cast<int>(k) + 1;
    if (!freqs.empty())
      againstParameter(t, out.stage("frequencies_vs_" + fileSafe(t.parameters[k]) + ".png"), p, freqs,
                       "Tracked modes against " + t.parameters[k], "frequency (Hz)");
    if (!margins.empty())
      againstParameter(t, out.stage("margins_vs_" + fileSafe(t.parameters[k]) + ".png"), p, margins,
                       "Check margins against " + t.parameters[k], "margin (%)");
  }
  pareto(t, out);
  gridMap(t, out);
}

}  // namespace mmv::cli

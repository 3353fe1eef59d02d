// The figures `mmvlab simulate --out` writes beside history.csv: what a reviewer looks
// at in a time run, each against its limit.
#include <cmath>

#include "facility/sensors.hpp"
#include "facility/table_programs.hpp"
#include "sim/cli/commands.hpp"
#include "sim/cli/figures.hpp"
#include "sim/core/text.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/time/simulation.hpp"

namespace mmv::cli {
namespace {

int columnOf(const SimulationRecord& rec, const std::string& name) {
  for (std::size_t c = 0; c < rec.columns.size(); ++c)
    if (rec.columns[c] == name) return static_cast<int>(c);
  return -1;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

/// Column c over time, scaled, as a series.
render::Series column(const SimulationRecord& rec, int c, const std::string& label, double scale = 1, double offset = 0) {
  render::Series s{label, {}, {}};
  for (const auto& row : rec.rows) {
    s.x.push_back(row[0]);
    s.y.push_back(scale * (row[static_cast<std::size_t>(c)] - offset));
  }
  return s;
}

/// A constant line over the run (a capacity, a limit), dashed, in `colour`.
render::Series level(const SimulationRecord& rec, double value, const std::string& label, int colour) {
  render::Series s{label, {rec.rows.front()[0], rec.rows.back()[0]}, {value, value}};
  s.dashed = true;
  s.colour_index = colour;
  return s;
}

void torquePlot(OutputDir& out, const SimulationResult& r, const std::string& title) {
  std::vector<render::Series> all;
  int colour = 1;
  for (const auto& t : r.torques) {
    const int c = columnOf(r.record, t.joint + "_torque_n_m");
    if (c < 0) continue;
    render::Series s = column(r.record, c, t.joint);
    s.colour_index = colour;
    all.push_back(s);
    if (t.capacity_nm > 0) {
      all.push_back(level(r.record, t.capacity_nm, t.joint + " capacity +-" + strf("%g", t.capacity_nm) + " N*m", colour));
      all.push_back(level(r.record, -t.capacity_nm, "", colour));
    }
    ++colour;
  }
  if (!all.empty()) figures::linePlot(out.stage("torques.png"), all, "Torquer torques and their capacities: " + title, "time (s)", "torque (N*m)");
}

void tablePlot(OutputDir& out, const SimulationResult& r, const std::string& title) {
  const int c = columnOf(r.record, "table_force_n");
  if (c < 0) return;
  const double payload = facility::TableSpec{}.payload_n;
  render::Series force = column(r.record, c, "actuator force along x");
  force.colour_index = 1;
  figures::linePlot(out.stage("table.png"),
                    {force, level(r.record, payload, strf("payload rating %g N", payload), 5),
                     level(r.record, r.carried_weight_n, strf("weight carried %.0f N", r.carried_weight_n), 4)},
                    "Table: actuator force and the weight it carries: " + title, "time (s)", "force (N)");
  // The stroke the program uses against the table's own (issue 36: table.png had none).
  const int x = columnOf(r.record, "table_x_m");
  if (x < 0) return;
  const double stroke = facility::TableSpec{}.stroke;
  render::Series pos = column(r.record, x, "table position along x", 100);
  pos.colour_index = 1;
  figures::linePlot(out.stage("table_stroke.png"),
                    {pos, level(r.record, 100 * stroke, strf("stroke +-%g cm", 100 * stroke), 5), level(r.record, -100 * stroke, "", 5)},
                    "Table: position against its stroke: " + title, "time (s)", "position (cm)");
}

void tipPlot(OutputDir& out, const SimulationResult& r, const std::string& title) {
  std::vector<render::Series> all;
  int colour = 1;
  for (std::size_t c = 1; c < r.record.columns.size(); ++c) {
    const std::string& name = r.record.columns[c];
    if (name.find(".tip_") == std::string::npos || !(endsWith(name, "_x_m") || endsWith(name, "_y_m"))) continue;
    const std::string point = name.substr(0, name.size() - 4), axis = name.substr(name.size() - 3, 1);
    render::Series s = column(r.record, static_cast<int>(c), point + " " + axis, 1e3, r.record.rows.front()[c]);
    s.colour_index = colour++;
    s.dashed = axis == "y";
    all.push_back(s);
  }
  if (!all.empty())
    figures::linePlot(out.stage("tips.png"), all, "Link tips' motion from where the run starts: " + title, "time (s)", "displacement (mm)");
}

/// The tips' elastic deflection (history.csv's `_elastic_` columns: position less where
/// rigid links at the same joint angles would put it), across each link solid and out of
/// the plane dashed; the slew's rigid metres, which swamp it in tips.png, are not in it.
void elasticPlot(OutputDir& out, const SimulationResult& r, const std::string& title) {
  std::vector<render::Series> all;
  int colour = 1;
  std::string last_point;
  for (std::size_t c = 1; c < r.record.columns.size(); ++c) {
    const std::string& name = r.record.columns[c];
    const bool across = endsWith(name, "_elastic_across_m"), out_of_plane = endsWith(name, "_elastic_out_m");
    if (!across && !out_of_plane) continue;
    const std::string point = name.substr(0, name.find("_elastic_"));
    if (!last_point.empty() && point != last_point) ++colour;
    last_point = point;
    render::Series s = column(r.record, static_cast<int>(c), point + (across ? " across the link" : " out of the plane"), 1e3);
    s.colour_index = colour;
    s.dashed = out_of_plane;
    all.push_back(s);
  }
  if (!all.empty())
    figures::linePlot(out.stage("tips_elastic.png"), all, "Link tips' elastic deflection (rigid motion removed): " + title,
                      "time (s)", "deflection (mm)");
}

/// A sensor's full scale as a reader of the figure says it: an encoder's in degrees, a
/// gyro's in deg/s, an accelerometer's in g (the record's own units stay SI).
std::string readableRange(double range, const std::string& unit) {
  if (unit == "rad") return strf("+-%.3g deg", range * 180 / M_PI);
  if (unit == "rad_per_s") return strf("+-%.3g deg/s", range * 180 / M_PI);
  if (unit == "m_per_s2") return strf("+-%.3g g", range / 9.80665);
  if (unit == "m_per_m") return strf("+-%.4g microstrain", range * 1e6);
  return strf("+-%.3g %s", range, unit.c_str());
}

void sensorPlot(OutputDir& out, const SimulationResult& r, const std::string& title) {
  std::vector<render::Series> all;
  int colour = 1;
  for (const auto& s : r.sensors) {
    int c = -1;
    for (std::size_t k = 0; k < r.record.columns.size() && c < 0; ++k)
      if (r.record.columns[k].rfind(s.name + "_", 0) == 0) c = static_cast<int>(k);
    const double range = s.range;
    if (c < 0 || !(range > 0)) continue;
    render::Series x = column(r.record, c, strf("%s (%s, range %s)", s.name.c_str(), s.type.c_str(), readableRange(range, s.unit).c_str()),
                              100 / range);
    x.colour_index = colour++;
    all.push_back(x);
  }
  if (all.empty()) return;
  all.push_back(level(r.record, 100, "range (+-100 %)", 0));
  all.push_back(level(r.record, -100, "", 0));
  figures::linePlot(out.stage("sensors.png"), all, "Sensors against their ranges: " + title, "time (s)", "reading (% of full scale)");
}

}  // namespace

void writeSimulationPlots(OutputDir& out, const SimulationResult& r, const std::string& title) {
  if (r.record.rows.size() < 2) return;
  try {
    torquePlot(out, r, title);
    tablePlot(out, r, title);
    tipPlot(out, r, title);
    elasticPlot(out, r, title);
    sensorPlot(out, r, title);
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
}

}  // namespace mmv::cli

#include "sim/io/config_sweep_report.hpp"

#include <cmath>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/report.hpp"

namespace mmv {

const std::vector<Field<TrackPoint>>& trackFields() {
  using json = nlohmann::ordered_json;
  using Opt = std::optional<json>;
  // clang-format off
  static const std::vector<Field<TrackPoint>> fields{
      {"sorted_mode", "", "%d", "the tracked mode's rank at this point (1-based)",
       [](const TrackPoint& t) -> Opt { return json(t.sorted_mode); }},
      {"frequency_hz", "Hz", "%.8g", "its frequency (null when unstable at this point)",
       [](const TrackPoint& t) -> Opt { return t.stable ? json(t.frequency_hz) : json(nullptr); }},
      {"mac_to_previous", "1", "%.6f", "MAC with the same track at the previous point",
       [](const TrackPoint& t) -> Opt { return json(t.mac_to_previous); }},
      {"synthesized_frequency_hz", "Hz", "%.8g", "the component synthesis's frequency for it",
       [](const TrackPoint& t) -> Opt { return json(t.synth_hz); }},
      {"synthesis_relative_error", "1", "%.6g", "synthesized / full - 1",
       [](const TrackPoint& t) -> Opt { return json(t.synth_error); }},
      {"synthesis_mac", "1", "%.6f", "MAC of the synthesized and the full shape",
       [](const TrackPoint& t) -> Opt { return json(t.synth_mac); }},
      {"verdict", "", "%s", "predicted, or why not (MAC < 0.9 or |error| > 1 %)",
       [](const TrackPoint& t) -> Opt { return json(t.verdict); }},
      {"strain_link", "", "%s", "the link with the most strain energy",
       [](const TrackPoint& t) -> Opt { return json(t.strain_link); }},
      {"state", "", "%s", "empty (followed), lost: why, or restarted: why",
       [](const TrackPoint& t) -> Opt { return json(t.state); }},
  };
  // clang-format on
  return fields;
}

std::string configSweepCsv(const ConfigSweepResult& r) {
  const auto all = [](const auto&) { return true; };
  std::ostringstream os;
  for (const auto& ax : r.axes) os << ax.joint << "_deg,";
  os << "point_kind,track," << fieldsCsvHeader(trackFields(), all) << '\n';
  for (const auto& p : r.points) {
    std::string lead;
    for (double a : p.angles_deg) lead += strf("%g,", a);
    lead += p.refined ? "refined," : "grid,";
    if (!p.solved) {  // one row saying why there is nothing: the verdict
      const auto why = [&](const Field<TrackPoint>& f) {
        return std::string(f.key) == "verdict" ? std::optional<nlohmann::ordered_json>("no equilibrium: " + p.failure)
                                               : std::optional<nlohmann::ordered_json>(nullptr);
      };
      os << lead << ',' << fieldsCsvRow(trackFields(), TrackPoint{}, all, why) << '\n';
    }
    for (std::size_t k = 0; k < p.tracks.size(); ++k)
      os << lead << k + 1 << ',' << fieldsCsvRow(trackFields(), p.tracks[k], all, [](const auto&) {
        return std::optional<nlohmann::ordered_json>();
      }) << '\n';
  }
  return os.str();
}

std::string configSweepText(const ConfigSweepResult& r) {
  std::ostringstream os;
  os << "Configuration map: system modes tracked by shape (MAC); in parentheses the synthesis error\n"
     << "of " << r.synthesis_method << " (%; * = not 'predicted': MAC < 0.9 or |err| > 1 %)\n"
     << strf("r: a point inserted where a track's MAC fell below %.1f; LOST: still below %.1f at the finest step\n"
             "(the track continues as another mode); RESTART: after a point without an equilibrium\n\n", kRefineMac, kLostMac);
  std::vector<std::string> head;
  for (const auto& ax : r.axes) head.push_back(ax.joint + "_deg");
  std::size_t tracks = 0;
  for (const auto& p : r.points) tracks = std::max(tracks, p.tracks.size());
  for (std::size_t k = 0; k < tracks; ++k) head.push_back(strf("track%zu_Hz (err_%%)", k + 1));
  Table t(head);
  for (const auto& p : r.points) {
    std::vector<std::string> row;
    for (double a : p.angles_deg) row.push_back(strf("%g", a) + (p.refined ? " r" : ""));
    if (!p.solved) row.push_back("no equilibrium (see below)");
    for (const auto& tp : p.tracks)
      row.push_back((tp.stable ? strf("%.4f (%+.2f)%s", tp.frequency_hz, 100 * tp.synth_error, tp.verdict == "predicted" ? " " : "*")
                               : std::string("UNSTABLE")) +
                    (tp.state.rfind("lost", 0) == 0 ? " LOST" : tp.state.rfind("restarted", 0) == 0 ? " RESTART" : ""));
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
  os << strf("\nTracking: %d points inserted to follow the shapes; worst MAC of a followed track %.3f; %d track%s lost\n",
             r.refined_points, r.min_tracking_mac, r.lost_tracks, r.lost_tracks == 1 ? "" : "s");
  for (const auto& p : r.points)
    for (std::size_t k = 0; k < p.tracks.size(); ++k)
      if (!p.tracks[k].state.empty()) os << strf("  track %zu at %g deg: ", k + 1, p.angles_deg[0]) << p.tracks[k].state << '\n';
  return os.str();
}

nlohmann::ordered_json configSweepJson(const ConfigSweepResult& r) {
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
  j["refined_points"] = r.refined_points;
  j["lost_tracks"] = r.lost_tracks;
  auto pts = nlohmann::ordered_json::array();
  for (const auto& p : r.points) {
    auto tr = nlohmann::ordered_json::array();
    for (const auto& t : p.tracks) tr.push_back(fieldsJson(trackFields(), t, [](const auto&) { return true; }));
    nlohmann::ordered_json pj = {{"angles_deg", p.angles_deg}, {"refined", p.refined}, {"solved", p.solved}, {"tracks", tr}};
    if (!p.solved) pj["failure"] = p.failure;
    pts.push_back(pj);
  }
  j["points"] = pts;
  return j;
}

}  // namespace mmv

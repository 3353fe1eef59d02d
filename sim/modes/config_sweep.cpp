#include "sim/modes/config_sweep.hpp"
#include "sim/core/progress.hpp"

#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/modes/tracking.hpp"

namespace mmv {

double GridAxis::count() const {
  if (!(step_deg > 0) || !(to_deg >= from_deg)) return 0;
  return std::floor((to_deg - from_deg) / step_deg + 1e-9) + 1;
}

std::vector<double> GridAxis::values() const {
  const double n = count();
  MMV_DEMAND(n <= kMaxValues);  // the reader refused more
  std::vector<double> v;
  for (int i = 0; i < static_cast<int>(n); ++i) v.push_back(from_deg + i * step_deg);
  return v;
}

namespace {

std::string anglesText(const std::vector<double>& a) {
  std::string s;
  for (double x : a) s += (s.empty() ? "" : ", ") + strf("%g", x);
  return s + " deg";
}

/// Walks the grid point by point, tracking the modes and refining the step where
/// the shapes change too fast to follow.
class Walker {
 public:
  Walker(const ArticleScene& scene, const ConfigSweepOptions& o, ConfigSweepResult& r) : scene_(scene), o_(o), r_(r), so_(o.synthesis) {
    so_.compare_modes = o.modes + 4;
  }

  /// Advances to `angles` (a grid point, or a refinement when !grid).
  void advance(const std::vector<double>& angles, bool grid, int depth = 0, const SynthesisResult* solved = nullptr) {
    SynthesisResult syn;
    std::string failure;
    if (solved) syn = *solved;
    else if (!solve(angles, syn, failure)) return fail(angles, grid, failure);
    if (prev_.cols() > 0 && depth < kMaxRefinements) {
      const ModeMatch m = matchModes(prev_.leftCols(std::min(prev_.cols(), syn.full_point_shapes.cols())), syn.full_point_shapes);
      if (*std::min_element(m.mac.begin(), m.mac.end()) < kRefineMac) {
        std::vector<double> mid(angles.size());
        for (std::size_t a = 0; a < angles.size(); ++a) mid[a] = 0.5 * (prev_angles_[a] + angles[a]);
        advance(mid, false, depth + 1);
        return advance(angles, grid, depth + 1, &syn);
      }
    }
    record(angles, grid, syn);
  }

 private:
  bool solve(const std::vector<double>& angles, SynthesisResult& syn, std::string& failure) {
    ArticleScene s = scene_;
    for (std::size_t a = 0; a < angles.size(); ++a)
      for (auto& jt : s.article.joints)
        if (jt.name == o_.axes[a].joint) jt.angle = angles[a] * M_PI / 180.0;
    try {
      syn = synthesize(s, so_);
    } catch (const NumericalError& e) {
      failure = e.what();
      return false;
    }
    if (r_.synthesis_method.empty()) r_.synthesis_method = syn.method;
    return true;
  }

  void fail(const std::vector<double>& angles, bool grid, const std::string& failure) {
    ConfigSweepPoint p;
    p.angles_deg = angles;
    p.solved = false;
    p.refined = !grid;
    p.failure = failure;
    ++r_.failed_points;
    r_.refined_points += !grid;
    r_.points.push_back(p);
    prev_.resize(0, 0);  // tracks restart after the gap
    restart_reason_ = "no equilibrium at " + anglesText(angles) + " (a limit point)";
  }

  void record(const std::vector<double>& angles, bool grid, const SynthesisResult& syn) {
    ConfigSweepPoint p;
    p.angles_deg = angles;
    p.refined = !grid;
    r_.refined_points += !grid;
    const int tracks = std::min(o_.modes, static_cast<int>(syn.full_point_shapes.cols()));
    std::vector<int> index(tracks);
    std::vector<double> mac(tracks, 1.0);
    const bool first = prev_.cols() == 0;
    if (first) {
      for (int k = 0; k < tracks; ++k) index[k] = k;
    } else {
      const ModeMatch m = matchModes(prev_.leftCols(std::min<Eigen::Index>(prev_.cols(), tracks)), syn.full_point_shapes);
      index = m.index;
      mac = m.mac;
      index.resize(tracks), mac.resize(tracks, 1.0);
    }
    Eigen::MatrixXd next(syn.full_point_shapes.rows(), tracks);
    for (int k = 0; k < tracks; ++k) {
      const SynthesisRow& row = syn.rows[index[k]];
      TrackPoint t;
      t.sorted_mode = row.mode;
      t.frequency_hz = row.full_hz;
      t.stable = row.full_hz > 0;
      t.mac_to_previous = mac[k];
      t.synth_hz = row.synth_hz;
      t.synth_error = row.relative_error;
      t.synth_mac = row.mac;
      t.verdict = row.verdict;
      t.strain_link = row.dominant_link;
      if (first && !restart_reason_.empty()) t.state = "restarted: " + restart_reason_;
      if (!first && mac[k] < kLostMac) {
        t.state = strf("lost: MAC %.2f from %s to %s at the finest step (a veering or crossing finer than it, or the equilibrium snapping to another shape)", mac[k],
                       anglesText(prev_angles_).c_str(), anglesText(angles).c_str());
        ++r_.lost_tracks;
      } else if (!first) {
        r_.min_tracking_mac = std::min(r_.min_tracking_mac, mac[k]);
      }
      p.tracks.push_back(t);
      next.col(k) = syn.full_point_shapes.col(index[k]);
    }
    prev_ = next;
    prev_angles_ = angles;
    restart_reason_.clear();
    r_.points.push_back(p);
  }

  const ArticleScene& scene_;
  const ConfigSweepOptions& o_;
  ConfigSweepResult& r_;
  SynthesisOptions so_;
  Eigen::MatrixXd prev_;  ///< tracked shapes at the previous point.
  std::vector<double> prev_angles_;
  std::string restart_reason_;
};

}  // namespace

ConfigSweepResult runConfigSweep(const ArticleScene& scene, const ConfigSweepOptions& o) {
  MMV_DEMAND(!o.axes.empty() && o.axes.size() <= 2);  // one or two axes (the CLI checks --grid)
  for (const auto& ax : o.axes)
    if (!scene.article.findJoint(ax.joint)) throw OptionError("--grid", ": " + scene.source + " has no joint '" + ax.joint + "'");
  ConfigSweepResult r;
  r.axes = o.axes;
  const std::vector<double> a0 = o.axes[0].values();
  const std::vector<double> a1 = o.axes.size() > 1 ? o.axes[1].values() : std::vector<double>{0.0};
  Walker walk(scene, o, r);
  const ProgressStage stage("configurations of the grid");
  for (std::size_t j = 0; j < a1.size(); ++j)
    for (std::size_t ii = 0; ii < a0.size(); ++ii) {
      progressCount(static_cast<long>(j * a0.size() + ii + 1), static_cast<long>(a0.size() * a1.size()), "configuration");
      const std::size_t i = (j % 2 == 0) ? ii : a0.size() - 1 - ii;  // back and forth
      std::vector<double> angles{a0[i]};
      if (o.axes.size() > 1) angles.push_back(a1[j]);
      walk.advance(angles, true);
    }
  return r;
}

}  // namespace mmv

#include "sim/modes/sweep.hpp"

#include <cmath>

#include "sim/core/errors.hpp"
#include "sim/modes/tracking.hpp"

namespace mmv {

std::vector<double> GridAxis::values() const {
  std::vector<double> v;
  for (int i = 0;; ++i) {
    const double a = from_deg + i * step_deg;
    if (a > to_deg + 1e-9 * step_deg) break;
    v.push_back(a);
  }
  return v;
}

SweepResult runSweep(const ArticleScene& scene, const SweepOptions& o) {
  MMV_DEMAND(!o.axes.empty() && o.axes.size() <= 2);  // one or two axes (the CLI checks --grid)
  for (const auto& ax : o.axes)
    if (!scene.article.findJoint(ax.joint)) throw SceneError(scene.source + ": the grid names an unknown joint '" + ax.joint + "'");
  SweepResult r;
  r.axes = o.axes;
  const std::vector<double> a0 = o.axes[0].values();
  const std::vector<double> a1 = o.axes.size() > 1 ? o.axes[1].values() : std::vector<double>{0.0};
  SynthesisOptions so = o.synthesis;
  so.compare_modes = o.modes + 4;

  Eigen::MatrixXd prev;  // tracked shapes at the previous point
  for (std::size_t j = 0; j < a1.size(); ++j) {
    for (std::size_t ii = 0; ii < a0.size(); ++ii) {
      const std::size_t i = (j % 2 == 0) ? ii : a0.size() - 1 - ii;  // back and forth
      ArticleScene s = scene;
      SweepPoint p;
      p.angles_deg.push_back(a0[i]);
      for (auto& jt : s.article.joints)
        if (jt.name == o.axes[0].joint) jt.angle = a0[i] * M_PI / 180.0;
      if (o.axes.size() > 1) {
        p.angles_deg.push_back(a1[j]);
        for (auto& jt : s.article.joints)
          if (jt.name == o.axes[1].joint) jt.angle = a1[j] * M_PI / 180.0;
      }
      SynthesisResult syn;
      try {
        syn = synthesize(s, so);
      } catch (const NumericalError& e) {
        p.solved = false;
        p.failure = e.what();
        ++r.failed_points;
        r.points.push_back(p);
        prev.resize(0, 0);  // tracks restart after the gap
        continue;
      }
      if (r.synthesis_method.empty()) r.synthesis_method = syn.method;
      const int available = static_cast<int>(syn.full_point_shapes.cols());
      const int tracks = std::min(o.modes, available);
      std::vector<int> index(tracks);
      std::vector<double> mac(tracks, 1.0);
      if (prev.cols() == 0) {
        for (int k = 0; k < tracks; ++k) index[k] = k;
      } else {
        const ModeMatch m = matchModes(prev, syn.full_point_shapes);
        index = m.index;
        mac = m.mac;
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
        p.tracks.push_back(t);
        next.col(k) = syn.full_point_shapes.col(index[k]);
        r.min_tracking_mac = std::min(r.min_tracking_mac, mac[k]);
      }
      prev = next;
      r.points.push_back(p);
    }
  }
  return r;
}

}  // namespace mmv

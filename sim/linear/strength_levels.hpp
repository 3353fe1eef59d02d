#pragma once
/// An exciter's levels held to the article's strength and to a stated deflection (the
/// table's dwells and random program, sim/linear/table_levels.hpp; the shaker's,
/// sim/linear/exciter.hpp; docs/strength.md): a stress output of the linear model at
/// every flexible link's root, hinges and tip (+y, and +z where the link bends out of the
/// plane: the peak of the interpolated moment is at one of them), each link tip's
/// motion relative to the base, and the links' static peak stress at the model's
/// equilibrium. A level may put a link at most its allowable over its factor less its
/// static stress (the two peaks added: conservative where they fall apart), and, when a
/// limit is stated, move no tip more than it.

#include <Eigen/Dense>

#include <string>
#include <vector>

#include "sim/linear/state_space.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// A level's stress and motion: the link nearest its limit (static plus dynamic over
/// allowable / factor) and the tip that moves most.
struct LevelStrength {
  std::string link;  ///< empty: no link with an allowable and a recoverable stress
  double static_pa = 0, amplitude_pa = 0, limit_pa = 0;
  std::string tip;
  double tip_amplitude_m = 0;
  double tip_link_m = 0;  ///< its link's length
};

/// A tip motion beyond this share of its link's length is no small deflection: the
/// linear model's level is flagged (a beam's linear theory holds to a few per cent).
inline constexpr double kLargeDeflection = 0.05;

class StrengthOutputs {
 public:
  /// Appends the stress and tip outputs to `outputs` (after the caller's own rows).
  StrengthOutputs(const ArticleScene& scene, int axes, std::vector<OutputSpec>& outputs);
  /// The links' static peak stress at `lm`'s equilibrium (its model built with the outputs).
  void setStaticStress(const ArticleScene& scene, const LinearModel& lm);
  /// Lowers `level` (per unit of input `input` of the response `H`: a force, an
  /// acceleration) to what the links' strength and `max_deflection_m` (0: none) allow,
  /// naming the bound in `limit` ("stress", "deflection"); the stress and motion there.
  LevelStrength hold(const Eigen::MatrixXcd& H, Eigen::Index input, double max_deflection_m, double& level, std::string& limit) const;
  /// The stress outputs' count (the rows from stressRow(0)); a random program's mean
  /// squares per unit spectrum come in that order.
  std::size_t stressRows() const;
  std::size_t stressRow(std::size_t k) const { return first_stress_ + k; }
  /// Lowers the spectrum `G` so that `crest` times each stress output's RMS (sqrt of
  /// `mean_squares`, per unit spectrum) stays within its link's room; the link that bound
  /// (empty: none).
  std::string capRandom(const std::vector<double>& mean_squares, double crest, double& G) const;
  /// Each link's largest stress over a time response of the model (`run`: samples x
  /// outputs, about the equilibrium): its static peak, the response's largest bending
  /// amplitude, its limit, and the sample where it peaks.
  struct LinkPeak {
    std::string link;
    double static_pa = 0, dynamic_pa = 0, limit_pa = 0;
    Eigen::Index sample = 0;
  };
  std::vector<LinkPeak> runPeaks(const Eigen::MatrixXd& run) const;

 private:
  struct Link {
    std::string name;
    std::size_t first = 0, count = 0;  ///< its stress outputs
    double static_pa = 0, limit_pa = 0;
  };
  std::vector<Link> links_;
  std::size_t first_stress_ = 0, first_tip_ = 0;
  int axes_ = 2;
  std::vector<std::string> tips_;
  std::vector<double> tip_link_m_;
};

}  // namespace mmv

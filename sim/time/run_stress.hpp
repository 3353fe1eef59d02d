#pragma once
/// Each link's stress through an article's time run (docs/strength.md, "In a time run").
///
/// At every sample, a flexible link's loads at its hinges are its springs' moments
/// (bending, torsion: sim/statics/link_stress.hpp hingeMoments) and the axial force from
/// the mobilizers' reaction forces (weight, a slew's inertia and centrifugal pull, the
/// closures: setReactionAxialForces), and its peak equivalent stress is taken over the
/// root, the hinges and the tip as in statics (peakStress): the same recovery, so a run
/// at rest reads the static stress of `modes`. A rigid link (a `check` run's copy) is
/// judged at its root, where its reactions give the loads exactly (rootReactionLoads);
/// along the link it is not recovered. The run keeps each link's peak (time, station,
/// face, loads), its margin of safety against the material's allowables with the
/// scene's factors, and the first sample at which the stress passed an allowable over
/// its factor.

#include <Eigen/Dense>
#include <Simbody.h>

#include <string>
#include <vector>

#include "article/article_spec.hpp"
#include "sim/model/model.hpp"
#include "sim/statics/link_stress.hpp"

namespace mmv {

/// One link's stress over a run.
struct LinkRunStress {
  std::string link, material;
  bool recovered = false;  ///< false: `why_not` says why (a section without its fibre distance).
  std::string why_not;
  bool root_only = false;  ///< a rigid link: its root only
  double peak_pa = 0;      ///< the largest equivalent stress at a sample
  double at_s = 0;         ///< when
  SectionLoads loads;      ///< there (loads.x: where along the link)
  std::string face;
  StrengthJudgement judgement;    ///< of the peak
  double limit_pa = 0;            ///< the smallest allowable / factor (0: no allowable)
  double first_exceeded_s = -1;   ///< the first sample above limit_pa (-1: never)
};

class RunStress {
 public:
  RunStress(const Model& model, const ArticleSpec& article);
  /// A column per link it recovers: `<link>_stress_pa`, its peak equivalent stress.
  std::vector<std::string> columns() const;
  /// At a sample: `s` realized to Acceleration, `q` every coordinate (Model::getQ
  /// order); appends a value per column to `row`.
  void sample(double t, const SimTK::State& s, const Eigen::VectorXd& q, std::vector<double>& row);
  /// Each link's run, scene order, peaks judged.
  std::vector<LinkRunStress> summary() const;

 private:
  struct Link {
    const LinkSpec* spec;
    const Material* material;
    const LinkAxis* axis;
    std::vector<const LinkAxis*> branches;  ///< the other links on its joint (rigid links' roots)
    SectionStrength section;
    LinkRunStress run;
  };
  const Model& model_;
  const ArticleSpec& article_;
  std::vector<Link> links_;
  bool any_recovered_ = false;
  SimTK::Vector_<SimTK::SpatialVec> reactions_;
};

}  // namespace mmv

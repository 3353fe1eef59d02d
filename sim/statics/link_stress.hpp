#pragma once
/// Internal loads, stresses and strength margins of the flexible links (docs/strength.md).
///
/// Where the discrete model carries a link's loads: hinge k (at x_k = (k - 1/2) h, h =
/// L / N; article/flexible_link.hpp) transmits its springs' moments, E I / h times its
/// angle on the planar model, k_i psi_i on the spatial one (torsion, out-of-plane and
/// in-plane bending: sim/model/rotation_spring.hpp), and the force of everything outboard
/// of it. A hinge's moment is E I times the mean curvature over its element, so it is the
/// beam's moment at x_k to O(h^2) (the midpoint rule); in statics under dead loads it is
/// the moment of the outboard loads about the hinge, exact up to the deformed geometry.
/// Between two hinges, and from the outer hinges to the root and the tip, the loads are
/// interpolated (extrapolated) linearly in x: a station's loads do not depend on where
/// the mesh's nodes fall and converge at second order in h where the moment is smooth
/// (a link of one segment has one hinge: its loads are taken as constant, first order).
/// A point mass on the link puts a kink in the moment: first order next to it.
///
/// Stress on the section's extreme fibres (fibre distances c, c_out from
/// article/section.hpp):
///   sigma = N / A -+ M c / I -+ M_out c_out / I_out   (a rectangle's or tube's corners),
///   sigma = N / A -+ |(M, M_out)| R / I              (a round rod),
///   tau = T * sectionTorsionShearPerTorque,            (torsion, spatial model)
/// and the equivalent stress max sqrt(sigma^2 + 3 tau^2) over the extreme fibres (von
/// Mises: an isotropic screening criterion; a composite's own criterion is the user's).
/// A positive in-plane moment bends the link counter-clockwise and compresses its +y face
/// (the strain gauges' convention, sim/model/stations.hpp strainRow); a positive
/// out-of-plane moment stretches its +z face.
///
/// Strength: a margin of safety MS = allowable / (factor * stress) - 1 for the yield and
/// the ultimate stress a material gives (article/section.hpp), with the scene's factors
/// (ArticleSpec::strength); the smaller governs. A material without an allowable is
/// stated ("no allowable: margin not judged"), never skipped.

#include <Eigen/Dense>
#include <Simbody.h>

#include <string>
#include <vector>

#include "article/article_spec.hpp"
#include "sim/model/model.hpp"
#include "sim/model/point_force.hpp"

namespace mmv {

/// The loads a section of a link carries (what the outboard part applies to the inboard).
struct SectionLoads {
  double x = 0;           ///< m from the link's root.
  double axial = 0;       ///< N, tension positive.
  double moment = 0;      ///< N*m, in the plane of motion (about the section's z).
  double moment_out = 0;  ///< N*m, out of the plane (about the section's y; spatial model).
  double torsion = 0;     ///< N*m, about the link (spatial model).
};

/// What a section's stress needs (article/section.hpp's formulas for its shape).
struct SectionStrength {
  double area = 0, second_moment = 0, second_moment_out = 0;  ///< m^2, m^4, m^4.
  double fibre = 0, fibre_out = 0;  ///< m, extreme fibre from the neutral axis (0: not known).
  double shear_per_torque = 0;      ///< Pa per N*m at the outer surface (0: not known).
  bool round = false;               ///< a round rod: the two moments add as a vector.
  double youngs_modulus = 0;        ///< Pa.
};
SectionStrength sectionStrength(const Material& m, const Section& s);

struct SectionStress {
  double tension = 0;      ///< Pa, the largest normal stress on the extreme fibres.
  double compression = 0;  ///< Pa, the smallest (negative where compressed).
  double shear = 0;        ///< Pa, the torsional shear at the surface.
  double equivalent = 0;   ///< Pa, max over the extreme fibres of sqrt(sigma^2 + 3 tau^2).
  double strain = 0;       ///< the largest |normal strain|, max(|tension|, |compression|) / E.
  /// The face where |sigma| peaks: "+y", "-y", "+z", "-z" or a corner ("-y+z"); "axis"
  /// when there is no bending (at most 1e-9 of the axial stress: round-off).
  std::string face;
};
SectionStress sectionStress(const SectionStrength& s, const SectionLoads& l);

/// The springs' moments at each hinge of link `axis` (root to tip) for coordinate values
/// `q` (Model::getQ order); axial force 0.
std::vector<SectionLoads> hingeMoments(const Model& model, const LinkAxis& axis, const Eigen::VectorXd& q);
/// The same, linear in a motion: the moments' change per unit of the coordinate motion
/// `dq` about `q` (a mode's shape over every coordinate), exact (the springs' moments
/// are quadratic in the angles, so a central difference is their derivative).
std::vector<SectionLoads> hingeMomentRates(const Model& model, const LinkAxis& axis, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& dq);
/// Sets each hinge's axial force in a static equilibrium `s` (realized to Position):
/// the part of the article outboard of the hinge is held by the hinge against its
/// weight, the dead loads on it and the closure forces on it (`closure_forces`,
/// sim/statics/closures.hpp closureForces), so N = F_outboard . e, e the link's
/// direction at the hinge (outwards).
void setStaticAxialForces(const Model& model, const LinkAxis& axis, const SimTK::State& s,
                          const std::vector<PointForce>& closure_forces, std::vector<SectionLoads>& hinges);
/// In motion: sets each hinge's axial force from the mobilizers' reaction forces of a state
/// realized to Acceleration (`reactions`, SimbodyMatterSubsystem::calcMobilizerReactionForces:
/// the parent's force on each child at its mobilizer, in Ground): N = -F . e, e the link's
/// direction at the hinge (outwards). Weight, inertia (a slew's centrifugal pull) and the
/// closures are in it; in a static equilibrium it is setStaticAxialForces' value.
void setReactionAxialForces(const Model& model, const LinkAxis& axis, const SimTK::State& s,
                            const SimTK::Vector_<SimTK::SpatialVec>& reactions, std::vector<SectionLoads>& hinges);
/// In motion: the loads at a link's root section from the reactions (as above): the
/// parent's force and moment on the link's first piece less those on the first pieces of
/// `branches` (the other links on its joint) mounted on it there, in the piece's frame:
/// x along the link (torsion, axial), z the in-plane normal (moment), y (moment out of
/// the plane). What a rigid link carries at its root; exact for the discrete model,
/// whatever the motion.
SectionLoads rootReactionLoads(const Model& model, const LinkAxis& axis, const std::vector<const LinkAxis*>& branches,
                               const SimTK::State& s, const SimTK::Vector_<SimTK::SpatialVec>& reactions);
/// The loads at `x` (m from the root) from the hinges' (ascending x): linear between
/// two, extrapolated linearly beyond the outer ones, constant with one hinge.
SectionLoads loadsAt(const std::vector<SectionLoads>& hinges, double x);

/// Where a link's equivalent stress peaks: over the root, every hinge and the tip (stress
/// is convex in the loads, the loads linear between those points: the peak of the
/// interpolated profile is at one of them).
struct LinkStressPeak {
  std::string link;
  bool recovered = false;  ///< false: `why_not` says why (a rigid link; no fibre distance).
  std::string why_not;
  SectionLoads loads;      ///< at the peak (loads.x: where); bending at round-off (face "axis") as 0.
  SectionStress stress;
};
LinkStressPeak peakStress(const LinkSpec& link, const SectionStrength& section, const std::vector<SectionLoads>& hinges);

/// The normal bending stress on `face` ("+y", "-y", "+z", "-z") of a section carrying
/// `l`: a positive in-plane moment compresses +y, a positive out-of-plane one stretches
/// +z (the strain gauges' convention); no axial part.
double faceBendingStress(const SectionStrength& s, const SectionLoads& l, const std::string& face);
/// The linear map from the coordinates `dofs` (indices into Model::getCoordinates) about
/// `q` to the bending stress on `face` of link `link` at `x` (m from its root): Pa per
/// unit of each coordinate, the loads interpolated between its hinges as everywhere
/// (loadsAt). The axial stress's change is of second order on a straight link and left
/// out, as in a mode's stress. Only the link's own hinges enter.
Eigen::RowVectorXd bendingStressRow(const Model& model, const LinkSpec& link, const SectionStrength& section, double x,
                                    const std::string& face, const Eigen::VectorXd& q, const std::vector<int>& dofs);

/// A stress judged against its material's allowables.
struct StrengthJudgement {
  bool judged = false;    ///< an allowable exists; else `note` says so.
  std::string criterion;  ///< "yield" or "ultimate": the governing one.
  double allowable = 0;   ///< Pa, the material's.
  double factor = 0;      ///< the scene's factor on it.
  double margin = 0;      ///< MS = allowable / (factor * stress) - 1 (stress > 0; else not judged).
  bool pass = true;
  std::string note;
};
StrengthJudgement judgeStress(double stress, const Material& m, const StrengthFactors& f);
/// The stress a material may carry: its smallest allowable over its factor (Pa; 0: it
/// gives none). A stress above it has a negative margin (judgeStress).
double strengthLimit(const Material& m, const StrengthFactors& f);

/// The static stress of every link of a solved equilibrium (closure forces from its
/// multipliers), root to tip per link, links in scene order.
struct LinkStaticStress {
  LinkStressPeak peak;
  StrengthJudgement judgement;
  std::string material;
};
std::vector<LinkStaticStress> staticLinkStress(const Model& model, const ArticleSpec& article, const SimTK::State& s,
                                               const Eigen::VectorXd& q, const std::vector<PointForce>& closure_forces);

/// Each flexible link's peak bending stress in the motion `dq` (over every coordinate)
/// about the equilibrium `q`, per unit of `dq` (axial force left out: a mode's is of
/// second order on a straight link). Links in scene order, rigid ones not recovered.
std::vector<LinkStressPeak> modalLinkStress(const Model& model, const ArticleSpec& article, const Eigen::VectorXd& q,
                                            const Eigen::VectorXd& dq);

}  // namespace mmv

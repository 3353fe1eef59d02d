#pragma once
/// The article as a drawing list (sim/core/drawing.hpp) for off-screen frames:
///
///  - each link along its deflected centerline (the stations' Hermite interpolation,
///    sim/model/stations.hpp, sampled 8 times per segment), with its real cross-section
///    (rectangular tube or solid rectangle: a box of width b out of the plane and height
///    h in it; round rod: a cylinder of its radius; sections under 15 mm are drawn 15 mm
///    so that link 3's 2.5 mm rods show), one colour per link;
///  - torquers as cylinders about the joint axis and tip masses as spheres, drawn with
///    the volume of steel of their mass (7850 kg/m^3: a size, not a claim about the
///    hardware's shape); the base excitation table as a slab under the base when the
///    scene has one, the gimbal's rings when it names one; closures as small spheres;
///  - the scene's sensors as glyphs by type (accelerometer: a cube; rate gyro: a
///    cylinder; encoder: a ring around its joint), each labelled with its name.
///
/// A mode is drawn as the linear model has it: each centreline point of the
/// equilibrium displaced by scale x its translation per unit modal coordinate (scale
/// chosen so the largest is 10 % of the article's extent unless given), coloured by
/// that translation's magnitude (a colour bar in m for the drawn shape), over a
/// translucent grey ghost of the equilibrium; the hardware stays at the equilibrium.

#include <optional>
#include <string>
#include <vector>

#include "sim/core/drawing.hpp"
#include "sim/core/mode_number.hpp"
#include "sim/modes/system_modes.hpp"

namespace mmv {

/// The article at the state `s` (realized to Position).
DrawList drawArticle(const ArticleScene& scene, const Model& model, const SimTK::State& s);

/// A shaker, schematic: its body off the article and the stinger to the driving point
/// `at` along the force's `direction` (world), labelled; a legend entry. drawArticle
/// draws the scene's own (`shaker:` at a station); place-sensors' review renders the
/// one its ranking chose for `at: auto`.
void addShakerDrawing(DrawList& d, const Eigen::Vector3d& at, const Eigen::Vector3d& direction, const std::string& label);

/// A placement's proposed sensors (world, m): blue boxes labelled `names` (empty: none),
/// apart from the scene's own red ones; coloured through the list's colour bar by `values`
/// when given (one per mark); a rod along each of a sensor's measuring directions (`axes`,
/// unit vectors, one list per sensor, or none); `legend` an entry for them (empty: none).
void addProposedSensors(DrawList& d, const std::vector<Eigen::Vector3d>& at, const std::vector<std::string>& names,
                        const std::vector<std::vector<Eigen::Vector3d>>& axes = {}, const std::vector<double>& values = {},
                        const std::string& legend = "");

/// The frames of one mode: the shape is computed once, each frame only
/// displaces it (an animation's 48 frames cost one Jacobian pass). `scale` > 0: metres
/// of drawing per unit modal coordinate; 0: automatic.
class ModeFrames {
 public:
  ModeFrames(const ArticleScene& scene, const SolvedScene& solved, ModeNumber mode, double scale);
  /// The mode at `phase` (-1..1: the shape's sign and size).
  DrawList frame(double phase, bool short_title = false) const;
  double scale() const { return scale_; }

 private:
  const ArticleScene& scene_;
  const SolvedScene& solved_;
  ModeNumber mode_;
  double scale_ = 1, peak_ = 0;  ///< peak_: the largest drawn translation, m.
  std::string dominant_;         ///< the link holding most of the mode's strain energy.
  std::string moving_;           ///< the link with the largest translation.
  std::vector<std::vector<Eigen::Vector3d>> rest_, shape_;
  DrawList hardware_;
};

/// Mode `mode` of a solved scene at phase `phase` (-1..1: the shape's sign and
/// size). `scale` > 0: metres of drawing per unit modal coordinate; 0: automatic.
/// Returns the list; `used_scale` receives the scale drawn.
DrawList drawMode(const ArticleScene& scene, const SolvedScene& solved, ModeNumber mode, double phase, double scale,
                  double* used_scale = nullptr, bool short_title = false);

}  // namespace mmv

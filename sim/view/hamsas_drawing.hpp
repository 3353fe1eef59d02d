#pragma once
/// The HAM-SAS isolator (article/hamsas.hpp) as a drawing list for off-screen frames:
/// each rigid body as the uniform box with its mass and principal moments of inertia
/// (sides sqrt(6 (I2 + I3 - I1) / m), at least 2 cm; the base, whose motion is
/// prescribed, as a slab under the legs), one colour per body group (optical table,
/// spring box, IP legs with their counterweights, little pendulums), the springs' and
/// joints' points as small spheres, the sensors labelled. A mode moves every body by
/// scale x its translation and small rotation in the mode (scale chosen so the largest
/// translation is 10 % of the isolator's extent unless given), coloured by that
/// translation, over a translucent ghost.

#include <optional>

#include "sim/core/drawing.hpp"
#include "sim/core/mode_number.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// A body's motion: translation (m) and small rotation vector (rad), world axes.
using BodyMotion = Eigen::Matrix<double, 6, 1>;

/// The isolator with every body (the base included) moved by `motion` x `scale` (a
/// time run's motion is micrometres: `scale` magnifies it, and the colour bar says by
/// how much), over a ghost of the design configuration; `title` follows the scene name.
DrawList drawHamsasMoved(const HamsasScene& scene, const HamsasModes& h, const std::vector<BodyMotion>& motion, double scale,
                         const std::string& title);

/// The isolator at rest (no mode) or mode `mode` at `phase` (-1..1).
/// `scale` > 0: metres of drawing per unit modal coordinate; 0: automatic.
DrawList drawHamsas(const HamsasScene& scene, const HamsasModes& h, std::optional<ModeNumber> mode = std::nullopt,
                    double phase = 1.0, double scale = 0, bool short_title = false);

}  // namespace mmv

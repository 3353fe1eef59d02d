#pragma once
/// Time runs of the HAM-SAS isolator (article/hamsas.hpp) through a nonlinear Simbody
/// model: every non-base body on a free mobilizer (quaternions), the base on a slider
/// along the ground motion's axis following the scene's `ground_motion` program, the
/// springs and dampers as one custom force element written with exact rotations
/// (point springs on the bodies' moving points; angular springs on the relative
/// rotation's angle-axis vector), uniform gravity. The spring rest offsets are the
/// linearization's preloads, so the design configuration is the model's equilibrium.
///
/// Recorded per sample: the ground's displacement, the optical table's and the spring
/// box's mass-centre displacements from the design (x, y, z), and the 8 sensors'
/// relative displacements (true values). Summarised as the article's runs: energy
/// balance (work of the prescribed ground motion, dissipation of the dampers), steps,
/// evaluations, wall time. A trade scores the table and the spring box.

#include <functional>

#include "sim/scene/scene.hpp"
#include "sim/time/simulation.hpp"
#include "sim/time/trade.hpp"

namespace mmv {

/// Throws SceneError without `ground_motion` or with ideal joints (time runs use the
/// stiff springs), NumericalError as simulate().
SimulationResult simulate(const HamsasScene& scene, const std::function<void(double)>& progress = {});

/// The isolator's trade problem: the optical table and the spring box scored, the
/// reference pair RK-Merson and ARKODE ERK (its lightly damped kHz joint modes keep BDF
/// at low order: a tight BDF run costs minutes, docs/hamsas.md), no segment ladder.
/// `duration` > 0 overrides the scene's.
TradeProblem hamsasTradeProblem(const HamsasScene& scene, double duration = 0);

}  // namespace mmv

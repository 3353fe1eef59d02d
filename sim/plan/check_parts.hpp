#pragma once
/// The pieces of `mmvlab check` (sim/plan/check.hpp), one file per group of lines.

#include <optional>
#include <string>
#include <vector>

#include "sim/modes/system_modes.hpp"
#include "sim/plan/check.hpp"
#include "sim/time/simulation.hpp"

namespace mmv::plan {

/// What every group reads: the scene, its modes about the held equilibrium, and the
/// time run of its rigid-link copy (open trees with something that moves or senses).
struct CheckInputs {
  const ArticleScene& scene;
  const CheckOptions& options;
  ModesReport modes;
  ArticleScene rigid;  ///< the scene with every link rigid.
  std::optional<SimulationResult> rigid_run;
  std::string rigid_run_skipped;  ///< why there is no rigid run (empty: there is one, or nothing to run).
};

/// The scene with every link rigid (one body per link; joints, masses and programs kept).
ArticleScene rigidCopy(const ArticleScene& scene);

/// A configuration the holding-torque search solved with the flexible links (its angles,
/// why it was chosen) and its links' static stress there.
struct HeldStress {
  std::string where;
  std::vector<LinkStaticStress> links;
};

/// Holding torques of locked joints and gimbal axes, worst over their ranges; the
/// peaks of the rigid-link run (slews); gimbal angles against their ranges. `solved`
/// gets each worst configuration's static stress.
void addTorqueLines(const CheckInputs& in, std::vector<CheckLine>& out, std::vector<HeldStress>& solved);
/// Each flexible link's static stress against its allowable with the scene's factor,
/// worst over the scene's configuration and those the torque search solved (a link's
/// root moment is its joint's holding torque: the worst torque is where a root-bent link
/// is worst); judged by the factor of safety alone (MS >= 0), not by --margin.
void addStrengthLines(const CheckInputs& in, const std::vector<HeldStress>& solved, std::vector<CheckLine>& out);
/// Each flexible link's root stress in the rigid-link run of the scene's programs (its
/// reactions: the inertial and gravity moment a slew or a table program puts there),
/// judged like the static lines; scenes whose programs move the article.
void addRunStrengthLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// On the table with a program: each link's static stress plus its largest bending
/// amplitude in the flexible linear model's response to the program over the scene's
/// run (the resonances the rigid run cannot see), judged like the static lines.
void addTableStrengthLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// Each sensor's peak signal against its range, with its signal-to-resolution ratio.
void addSensorLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// Payload, stroke, bandwidth (table scenes); modal content in the band.
void addTableAndModeLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// The spatial model: the modes in the band that leave the plane against their nearest
/// in-plane mode, and the out-of-plane response under the scene's programs.
void addPlanarityLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// The extra shaker (scenes with `shaker:`) on the scene's accelerometers: its armature's
/// shift of the modes in the band, and each mode seen above the resolution under a
/// sine dwell within the shaker's force and stroke and the sensors' range.
void addShakerLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// The article's envelope against the lab (scenes with `lab:`).
void addLabLines(const CheckInputs& in, std::vector<CheckLine>& out);
/// Values no lab article has, each with the likely unit mistake.
void addPlausibilityLines(const CheckInputs& in, std::vector<CheckLine>& out);

/// A line with its margin judged.
CheckLine makeLine(const std::string& group, const std::string& id, const std::string& requirement, double demand, double capacity,
                   const std::string& unit, const std::string& note, double required_margin_pct);

}  // namespace mmv::plan

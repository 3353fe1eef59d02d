#pragma once
/// Builds the Simbody model of a planar article from its scene.
///
/// Each joint becomes a pin about world z between the parent's tip (or the base frame)
/// and the root piece of its first child link; further children of the same joint
/// (branches) are welded to that root piece at their mount angles, so all branches
/// turn with the joint. Each flexible link becomes the pieces and hinges of
/// flexible_link.hpp, every hinge a pin with a linear rotational spring E*I/h. A
/// torquer is a body welded to the parent side of its joint; a tip mass a body welded
/// to its link's tip. Locked joints are marked held (not degrees of freedom); servo
/// joints get a rotational spring to the commanded angle; free joints get nothing.
///
/// Named points: "<link>.root", "<link>.h<k>" (hinge k = 1..N), "<link>.tip", and
/// "<joint>" at each joint's axis.

#include <memory>

#include "facility/table_programs.hpp"
#include "sim/model/model.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// What the model is for: the analyses (statics, modes, linear models) see the article
/// as the scene states it; a time run also builds what only a run drives (the shaker's
/// armature and stinger when `shaker.program` is given, sim/model/attachments.hpp).
enum class ModelUse { Analysis, TimeRun };

/// Slews of locked joints and the table's program become Simbody prescribed motions
/// (sim/model/motions.hpp). Throws
/// std::invalid_argument from the facility models (a slew outside the joint range,
/// a bad CSV profile).
std::unique_ptr<Model> buildArticleModel(const ArticleScene& scene, ModelUse use = ModelUse::Analysis);

}  // namespace mmv

#pragma once
/// The unit of a scene key's value, as docs/scene-format.md states it, for the labels of
/// figures whose axis is a scene key (a sweep's parameter): "links.link3.length" -> "m".

#include <string>

namespace mmv {

/// The unit of the value at `key`, a dotted scene path ("sections.rod.radius") or its
/// CSV column name ("sections_rod_radius"), by its last name (`radius`, `youngs_modulus`,
/// `angle_deg`, ...); "" when the key has no unit (a ratio, a count) or is not known.
std::string sceneKeyUnit(const std::string& key);

/// `key` with its unit for an axis: "links_link3_length (m)"; the key alone without one.
std::string sceneKeyLabel(const std::string& key);

}  // namespace mmv

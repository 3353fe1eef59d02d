#pragma once
/// The chosen sensors' test geometry, for the lab's acquisition and modal software: the
/// UFF file (a node per chosen station, numbered by PlacementCandidate::node so that a
/// station keeps its number in every run; a trace line per link through its chosen
/// stations; the target modes' predicted shapes at the nodes) and the channel table
/// (channels.csv, one list: placementChannelFields).

#include <string>
#include <vector>

#include "sim/io/fields.hpp"
#include "sim/io/uff.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// A chosen sensor direction: a data-acquisition channel.
struct PlacementChannel {
  int channel = 0;  ///< 1-based, in row order
  const PlacementCandidate* candidate = nullptr;
  const PlacementDirection* direction = nullptr;
};
std::vector<PlacementChannel> placementChannels(const PlacementStudy& s);
/// channel, node, station, link, axis, direction_x/y/z, quantity, unit, and two columns the
/// lab fills (sensitivity_mv_per_unit, serial: empty).
const std::vector<Field<PlacementChannel>>& placementChannelFields();
std::string placementChannelsCsv(const PlacementStudy& s);

/// The UFF geometry and predicted shapes of the chosen set (the article's placements).
uff::File placementGeometry(const PlacementStudy& s, const std::string& scene_name);

}  // namespace mmv

#pragma once
/// Writers for the sensors' mass loading of a placement (SensorLoading,
/// sim/modes/place_sensors.hpp): per target mode, one field list (loadingModeFields:
/// placement.json's mass_loading records and the text table's values).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/io/fields.hpp"
#include "sim/modes/place_sensors.hpp"

namespace mmv {

/// mode, frequency_hz, loaded_mode, loaded_hz, shift, first_order_shift, mac.
const std::vector<Field<SensorLoading::Mode>>& loadingModeFields();
/// pass, changed, settled, repeats: placement.json's mass_loading.iterations records.
const std::vector<Field<LoadedIteration>>& loadedIterationFields();
nlohmann::ordered_json loadingJson(const SensorLoading& l);
std::string loadingText(const SensorLoading& l);

}  // namespace mmv

#include "sim/scene/key_units.hpp"

#include <utility>

namespace mmv {

std::string sceneKeyUnit(const std::string& key) {
  // Longest names first: a key ends in one of these after a '.' or '_' (or is it).
  static const std::pair<const char*, const char*> kUnits[] = {
      {"max_acceleration_deg_s2", "deg/s^2"}, {"max_rate_deg_s", "deg/s"}, {"rate_deg_s", "deg/s"},
      {"youngs_modulus", "Pa"},               {"shear_modulus", "Pa"},      {"servo_stiffness", "N*m/rad"},
      {"torque_capacity", "N*m"},             {"rotary_inertia", "kg*m^2"}, {"ring_inertia", "kg*m^2"},
      {"second_moment", "m^4"},               {"sample_rate_hz", "Hz"},     {"direction_deg", "deg"},
      {"mount_angle_deg", "deg"},             {"table_mass", "kg"},         {"ring_mass", "kg"},
      {"density", "kg/m^3"},                  {"range_deg", "deg"},         {"angle_deg", "deg"},
      {"frequency_hz", "Hz"},                 {"from_hz", "Hz"},            {"to_hz", "Hz"},
      {"to_deg", "deg"},                      {"duration", "s"},            {"start_s", "s"},
      {"ramp_s", "s"},                        {"length", "m"},              {"radius", "m"},
      {"area", "m^2"},                        {"mass", "kg"},               {"b", "m"},
      {"h", "m"},                             {"t", "m"},
      {"fibre_distance_out", "m"},            {"fibre_distance", "m"},      {"yield_strength", "Pa"},
      {"ultimate_strength", "Pa"},
  };
  for (const auto& [name, unit] : kUnits) {
    const std::string n(name);
    if (key == n) return unit;
    if (key.size() > n.size() && key.compare(key.size() - n.size(), n.size(), n) == 0) {
      const char before = key[key.size() - n.size() - 1];
      if (before == '.' || before == '_') return unit;
    }
  }
  return "";
}

std::string sceneKeyLabel(const std::string& key) {
  const std::string unit = sceneKeyUnit(key);
  return unit.empty() ? key : key + " (" + unit + ")";
}

}  // namespace mmv

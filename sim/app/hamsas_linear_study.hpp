#pragma once
/// `frf` and `rom` on a HAM-SAS isolator scene (sim/hamsas/hamsas_modes.hpp): the 6 x 6
/// ground-to-optical-table transmissibility (optionally over one parameter's values) and
/// the 8 x 8 model from the spring box's actuators to its sensors, reduced.

#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "sim/app/linear_study.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv::app {

struct HamsasFrfStudy {
  std::vector<double> f;               ///< the grid, Hz (checkLinearRequest's)
  std::vector<Eigen::MatrixXcd> T;     ///< per frequency, table DOF x ground DOF (hamsasDofName)
  Eigen::MatrixXcd T10;                ///< at 10 Hz
  std::string vary_key, vary_unit;     ///< `vary`'s parameter (empty: none)
  std::vector<HamsasVaryPoint> varied;
  nlohmann::ordered_json json;         ///< `frf --json`
  std::string text, csv;               ///< the report, transmissibility.csv
};

/// The transmissibility; `request.inputs`/`outputs`/`target_error` do not apply (a
/// UsageError), `request.vary` is one "KEY=V1,V2,..." of hamsasParameters().
HamsasFrfStudy runHamsasFrfStudy(const HamsasScene& scene, const LinearRequest& request);

struct HamsasRomStudy {
  std::vector<double> f;  ///< the grid, Hz, the error was measured on
  StateSpace full;
  ReducedModel red;
  ModelError err;
  nlohmann::ordered_json json;  ///< rom.json, `rom --json`
  std::string text;
};

HamsasRomStudy runHamsasRomStudy(const HamsasScene& scene, const LinearRequest& request);

}  // namespace mmv::app

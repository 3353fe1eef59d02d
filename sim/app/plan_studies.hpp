#pragma once
/// `check` (feasibility, sim/plan/check.hpp) and `place-sensors` (sim/modes/place_sensors.hpp,
/// the isolator's: sim/hamsas/hamsas_placement.hpp) as studies.

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/app/options.hpp"
#include "sim/app/study.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/linear/exciter.hpp"
#include "sim/linear/table_levels.hpp"
#include "sim/modes/place_sensors.hpp"
#include "sim/plan/check.hpp"

namespace mmv::app {

/// `check`'s options, declared once (sim/app/options.hpp).
struct CheckParams {
  double margin = 20;     ///< %: a margin below it is a warning.
  Band band{0.1, 50};     ///< Hz: the modes of interest.

  template <class S, class V>
  static void fields(S& s, V&& v) {
    v(s.margin, Option("margin", "Required margin: a smaller one is a warning").unit("%").range(0, 99));
    v(s.band, Option("band_hz", "The modes of interest, F_MIN_HZ:F_MAX_HZ (report: 0.1-50 Hz)").unit("Hz").flag("--band"));
  }
};

struct CheckRequest : CheckParams {
  Front front = Front::Cli;
};

struct CheckStudy {
  CheckReport report;
  nlohmann::ordered_json json;
  std::string text, markdown;
};

/// The feasibility report of an article scene (a HAM-SAS scene is a UsageError).
CheckStudy runCheckStudy(const Scene& scene, const CheckRequest& request);

struct PlacementRequest {
  std::vector<int> modes;  ///< target modes, 1-based; empty: every vibration mode below `below_hz`.
  double below_hz = 50;    ///< > 0; not with `modes`.
  double spacing_m = 0.1;  ///< 1e-3 .. 100 m.
  int count = 8;           ///< 1 .. 100000.
  bool triaxial = false;
  std::string method = "efi";  ///< efi, mke or dpr.
  bool below_given = false;    ///< `below_hz` was given (then not `modes` too).
  std::vector<std::string> tam;  ///< guyan, irs, serep (or all): test-analysis models on the chosen sensors
  double sensor_mass_kg = 0;     ///< 0 .. 100 kg: each chosen sensor's mass, the modes solved again with them (0: not)
  double min_separation_m = 0;   ///< 0 .. 100 m between chosen stations (0: none)
  std::vector<std::string> keep_out;  ///< LINK:FROM_M:TO_M, stretches no sensor may go on
  int channels = 0;              ///< > 0: the budget in channels, which sets `count` (a triaxial block costs 3)
  bool keep_scene_sensors = false;  ///< the scene's accelerometers kept in advance, counted in the budget
  /// The accelerometer placed, from the scene's catalogue (`instruments:`); empty: the
  /// scene's `accelerometer`. Its mass loads the model (`sensor_mass_kg` overrides it),
  /// its range and resolution set the exciter's levels, a triaxial one places blocks.
  std::string instrument;
  bool iterate_loaded = false;  ///< placed again on the loaded model until the set carries itself
  /// > 0: place strain gauges or piezo films of this length (m, 1e-3 .. 100) instead of
  /// accelerometers (PlacementOptions::strain_span_m): the planar article, effective
  /// independence, uniaxial, massless; no shaker or table levels (they are planned on
  /// accelerometers) and no test_geometry.uff (its records hold motions).
  double strain_span_m = 0;
  /// > 0 (m, 1e-6 .. 100): the table's dwell levels hold every tip's motion relative to
  /// the table within it (sim/linear/table_levels.hpp); 0: no deflection limit.
  double max_deflection_m = 0;
  Front front = Front::Cli;
};

struct PlacementStudyResult {
  PlacementStudy study;
  std::optional<HamsasModes> isolator_modes;  ///< a HAM-SAS scene's (its review renders draw them)
  nlohmann::ordered_json json;
  std::string text;
  std::string tam_csv;  ///< tam.csv (empty without TAMs)
  std::optional<MatContents> tam_mat;  ///< tam.mat (none without TAMs)
  std::string channels_csv, geometry_uff;  ///< the article's test geometry: channels.csv, test_geometry.uff
  std::optional<ExciterStudy> exciter;     ///< the scene's shaker (`shaker:`), on the chosen sensors
  std::string exciter_csv, exciter_ranking_csv;  ///< exciter.csv, exciter_ranking.csv (empty without a shaker)
  std::string sensors_vtp;  ///< sensors.vtp, the chosen channels for ParaView (sim/io/vtk_export.hpp; the article's)
  std::optional<TableLevels> table_levels;  ///< a scene on the base table: its dwell levels per target mode
  /// The verdicts a review reads first, a line each (summary.png's text): the targets,
  /// the set, its information and AutoMAC, each TAM, the sensors' mass, the exciters.
  std::vector<std::string> summary_lines;
};

PlacementStudyResult runPlacementStudy(const Scene& scene, const PlacementRequest& request);

}  // namespace mmv::app

#pragma once
/// The study layer: one function per verb, taking a typed request and returning a typed
/// result, for every front end (the `mmvlab` executable, the Python module). A front end
/// parses its own syntax into a request; the study checks what the user gave once, names
/// it the way that front end spells it (`--target-error` on the command line,
/// `target_error=` in Python), runs the analysis and returns plain data with its JSON
/// and text forms, made by the same writers whichever front end asked.

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/scene/scene.hpp"

namespace mmv::app {

/// Who asked: decides only how an option is named in a message.
enum class Front { Cli, Python };

/// The option `cli_flag` ("--target-error") as `front` spells it ("target_error").
std::string optionName(Front front, const std::string& cli_flag);

struct SceneRequest {
  std::string path;               ///< empty: the embedded default scene.
  std::vector<std::string> sets;  ///< KEY=VALUE patches, checked by the reader with their position.
  int segments = 0;               ///< > 0: every flexible link's segments.
  bool no_gravity = false;
  bool strict = false;  ///< implausible values (sim/scene/plausibility.hpp) are errors, not warnings.
  Front front = Front::Cli;
};

struct LoadedScene {
  Scene scene;
  std::vector<std::string> warnings;  ///< as the CLI prints them on stderr, one per line.
};

/// Reads and checks the scene with its patches; `--segments`, `--no-gravity` and
/// `--strict` applied and checked here, once.
LoadedScene loadScene(const SceneRequest& request);

/// Sets every flexible link's segments of an article scene (1 .. limits::kMaxSegments,
/// else a UsageError naming the option); the notes it makes join `warnings`.
void applySegments(Scene& scene, int segments, Front front, std::vector<std::string>& warnings);

/// A number the user gave, checked against its range [lo, hi] (`open_low`: (lo, hi];
/// hi = infinity: no upper bound); a UsageError naming the option as `front` spells it.
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
void checkRange(Front front, const std::string& cli_flag, double value, double lo, double hi, bool open_low = false);

/// Checks named points and stations against the article (UsageError naming `option`).
std::vector<std::string> checkedPoints(const std::vector<std::string>& names, const ArticleSpec& article,
                                       const std::string& option);

/// A whole field of text as a finite number ("2.5", "-1e-3"); nullopt for anything else
/// ("", "2.5x", "nan", "inf"). The one number parser of the options the studies split
/// (--grid, --vary, --band).
std::optional<double> finiteNumber(const std::string& text);

/// The article of `scene`; a HAM-SAS scene is a UsageError naming `verb`.
const ArticleScene& articleOf(const Scene& scene, const std::string& verb);

/// A result that holds a NaN or infinity is a NumericalError naming where, never printed.
void checkResultFinite(const std::string& text);
void checkResultFinite(const nlohmann::ordered_json& json);

}  // namespace mmv::app

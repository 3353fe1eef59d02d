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
  std::optional<int> segments;    ///< every flexible link's segments (a patch, SceneFlags).
  bool no_gravity = false;
  bool strict = false;  ///< implausible values (sim/scene/plausibility.hpp) are errors, not warnings.
  Front front = Front::Cli;
};

struct LoadedScene {
  Scene scene;
  std::vector<std::string> warnings;  ///< as the CLI prints them on stderr, one per line.
  SceneRequest request = {};          ///< what was read, for withSegments.
};

/// Reads and checks the scene with its patches: `--segments` and `--no-gravity` are
/// patches the reader checks (SceneFlags), named as the front end spells them;
/// `--strict` applied here, once.
LoadedScene loadScene(const SceneRequest& request);

/// `loaded` read again from the same text and patches with `segments` (0: the scene's own)
/// instead of its request's: a Python study's `segments=`, through the same reader.
/// `warnings` holds only what the new count said.
LoadedScene withSegments(const LoadedScene& loaded, std::optional<int> segments);

/// `segments` and `no_gravity` as the scene reader's patches, labelled the way `front`
/// spells them ("--segments 16" / "segments=16").
SceneFlags sceneFlags(std::optional<int> segments, bool no_gravity, Front front);

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

#include "sim/cli/commands.hpp"

#include "sim/app/component_studies.hpp"

#include "sim/core/text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>

#include "sim/io/finite_check.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/scene/plausibility.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::cli {

Scene loadScene(const SceneArgs& args) {
  app::LoadedScene loaded = app::loadScene(sceneRequest(args));
  for (const auto& w : loaded.warnings) std::cerr << w << '\n';
  return std::move(loaded.scene);
}

app::SceneRequest sceneRequest(const SceneArgs& args) {
  app::SceneRequest r;
  r.path = args.scene_path;
  r.sets = args.sets;
  r.segments = args.segments;
  r.no_gravity = args.no_gravity;
  r.strict = args.strict;
  return r;
}

ArticleScene loadArticleScene(const SceneArgs& args, const std::string& command) {
  return app::articleOf(loadScene(args), command);
}

int guarded(const std::function<int()>& body) {
  // Messages may quote the user's bytes (a scene value, a key, a path): escaped, so
  // control bytes and invalid UTF-8 never reach the terminal raw.
  const auto say = [](const char* prefix, const std::exception& e, int code) {
    std::cerr << prefix << printable(e.what()) << '\n';
    return code;
  };
  try {
    return body();
  } catch (const UsageError& e) {
    return say("mmvlab: ", e, kUsage);
  } catch (const OutputError& e) {
    return say("mmvlab: ", e, kCannotCreate);
  } catch (const StdoutError& e) {
    return say("mmvlab: ", e, kIoError);
  } catch (const SceneFileError& e) {
    return say("mmvlab: ", e, kNoInput);
  } catch (const SceneError& e) {
    return say("", e, kDataError);
  } catch (const NumericalError& e) {
    return say("mmvlab: numerical failure: ", e, kNumericalFailure);
  } catch (const UnavailableError& e) {
    return say("mmvlab: not available in this installation: ", e, kUnavailable);
  } catch (const std::exception& e) {
    return say("mmvlab: internal error: ", e, kInternal);
  }
}

namespace {

/// Standard output that did not take the result (a full disk, a closed pipe) fails the
/// command, so an --out committed before is put back (OutputDir's transaction).
void flushStdout() {
  std::cout.flush();
  if (!std::cout) throw StdoutError("cannot write to standard output (disk full or pipe closed?)");
}

}  // namespace

void emitResult(const std::string& text) {
  checkResultFinite(text);
  std::cout << text;
  flushStdout();
}

void emitResult(const nlohmann::ordered_json& json) {
  checkResultFinite(json);
  std::cout << json.dump(2) << '\n';
  flushStdout();
}

std::pair<double, double> parseBand(const std::string& band) {
  const auto colon = band.find(':');
  if (colon == std::string::npos) throw UsageError("--band: expected F_MIN_HZ:F_MAX_HZ (got '" + band + "')");
  const std::optional<double> lo = app::finiteNumber(band.substr(0, colon)), hi = app::finiteNumber(band.substr(colon + 1));
  if (!lo || !hi || !(*hi > *lo) || !(*lo >= 0))
    throw UsageError("--band: expected 0 <= F_MIN_HZ < F_MAX_HZ (got '" + band + "')");
  return {*lo, *hi};
}

int runSceneCommand() {
  std::cout << defaultSceneYaml() << std::flush;
  return kOk;
}

}  // namespace mmv::cli

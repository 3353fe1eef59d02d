#include "fuzz_targets.hpp"

#include <cmath>
#include <regex>
#include <typeinfo>
#include <variant>

#include <nlohmann/json.hpp>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/hamsas/hamsas_modes.hpp"
#include "sim/io/finite_check.hpp"
#include "sim/io/hamsas_report.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/plan/check.hpp"
#include "sim/io/run_dir.hpp"
#include "sim/io/uff_read.hpp"
#include "sim/scene/scene.hpp"
#include "sim/scene/design_sweep_spec.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace mmv::fuzz {
namespace {

const char* const kSource = "fuzz.yaml";

/// A scene error must start with fuzz.yaml:LINE:COL: (the contract's "file:line:col").
std::optional<std::string> judgeSceneError(const SceneError& e) {
  static const std::regex positioned(R"(^fuzz\.yaml:\d+:\d+: )");
  if (std::regex_search(e.what(), positioned)) return std::nullopt;
  return "scene error without fuzz.yaml:line:col: " + printable(e.what());
}

/// A named user error whose message starts with `prefix` (the file or the override
/// it is about) keeps the contract; anything else is judged as judgeException does.
std::optional<std::string> judgeNamed(std::exception_ptr p, const std::string& prefix) {
  auto named = [&](const char* kind, const std::exception& e) -> std::optional<std::string> {
    if (std::string(e.what()).rfind(prefix, 0) == 0) return std::nullopt;
    return std::string(kind) + " error that does not name " + prefix + ": " + printable(e.what());
  };
  try {
    std::rethrow_exception(p);
  } catch (const SceneError& e) {
    return named("scene", e);
  } catch (const SceneFileError& e) {
    return named("file", e);
  } catch (const UsageError& e) {
    return named("usage", e);
  } catch (...) {
    return judgeException(std::current_exception());
  }
}

}  // namespace

std::optional<std::string> specTarget(const std::string& text) {
  try {
    const DesignSweepSpec spec = parseSweepSpec(text, kSource, ".");
    double n = 1;
    for (const auto& p : spec.parameters) n *= spec.design == DesignSweepSpec::Design::Grid ? static_cast<double>(p.gridValues().size()) : 1.0;
    if (spec.design == DesignSweepSpec::Design::LatinHypercube) n = spec.lhs_samples;
    if (n <= 10000) {
      const auto points = sweepPoints(spec);
      if (static_cast<double>(points.size()) != n) return strf("%zu points where the spec makes %.0f", points.size(), n);
      for (const auto& pt : points)
        for (double x : pt)
          if (!std::isfinite(x)) return std::string("a point holds a value that is not finite");
    }
    return std::nullopt;
  } catch (...) {
    return judgeException(std::current_exception());
  }
}

std::optional<std::string> uffTarget(const std::string& text) {
  try {
    (void)uff::read(text, "fuzz.uff");
    return std::nullopt;
  } catch (...) {
    return judgeNamed(std::current_exception(), "fuzz.uff");
  }
}

std::optional<std::string> setTarget(const std::string& text) {
  std::vector<std::string> sets;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line) && sets.size() < 16;) sets.push_back(line);
  try {
    (void)parseScene(defaultSceneYaml(), "<default scene>", sets);
    return std::nullopt;
  } catch (...) {
    return judgeNamed(std::current_exception(), "--set ");
  }
}

std::optional<std::string> runDirTarget(const std::string& text) {
  namespace fs = std::filesystem;
  // One directory for the process's inputs, removed when the process ends.
  struct RunDir {
    fs::path path = fs::temp_directory_path() / ("mmvlab_fuzz_run_" + std::to_string(::getpid()));
    RunDir() {
      fs::create_directories(path);
      std::ofstream(path / "scene.yaml") << defaultSceneYaml();
    }
    ~RunDir() {
      std::error_code ec;
      fs::remove_all(path, ec);
    }
  };
  static const RunDir run_dir;
  const fs::path& dir = run_dir.path;
  const std::size_t at = text.find("\n@@\n");
  const std::string json = at == std::string::npos ? text : text.substr(0, at);
  const std::string csv = at == std::string::npos ? std::string() : text.substr(at + 4);
  std::ofstream(dir / "run.json", std::ios::binary) << json;
  std::ofstream(dir / "history.csv", std::ios::binary) << csv;
  std::ofstream(dir / "states.csv", std::ios::binary) << csv;
  try {
    (void)readRunDir(dir.string());
    return std::nullopt;
  } catch (...) {
    return judgeNamed(std::current_exception(), dir.string());
  }
}

/// Any exception: a named user or numerical error keeps the contract, anything else
/// (an internal error, a third party's exception) breaks it.
std::optional<std::string> judgeException(std::exception_ptr p) {
  try {
    std::rethrow_exception(p);
  } catch (const SceneError& e) {
    return judgeSceneError(e);
  } catch (const NumericalError&) {
    return std::nullopt;
  } catch (const std::exception& e) {
    return std::string("uncaught ") + typeid(e).name() + ": " + printable(e.what());
  } catch (...) {
    return std::string("uncaught exception of a type not derived from std::exception");
  }
}

std::optional<std::string> judgeOutput(const std::string& text, const nlohmann::ordered_json& json) {
  if (const std::string at = firstNonFiniteLine(text); !at.empty()) return "NaN or inf in the text output, " + at;
  if (const std::string at = firstNonFiniteJson(json); !at.empty()) return "NaN or inf in the JSON output at " + at;
  return std::nullopt;
}

std::optional<std::string> readerTarget(const std::string& text) {
  try {
    (void)parseScene(text, kSource);
    return std::nullopt;
  } catch (...) {
    return judgeException(std::current_exception());
  }
}

std::optional<std::string> modesTarget(const std::string& text) {
  try {
    Scene scene = parseScene(text, kSource);
    if (auto* h = std::get_if<HamsasScene>(&scene)) {
      const HamsasModes m = analyseHamsas(h->isolator);
      return judgeOutput(hamsasModesText(*h, m, 12), hamsasModesJson(*h, m, 12));
    }
    auto& a = std::get<ArticleScene>(scene);
    overrideSegments(a, 2);
    ModesOptions opt;
    opt.with_shapes = true;
    ModesReport rep = runModes(a, opt);
    for (const auto& w : plausibilityWarnings(a, rep)) rep.warnings.push_back(w);
    return judgeOutput(formatModesText(rep), modesToJson(rep));
  } catch (...) {
    return judgeException(std::current_exception());
  }
}

}  // namespace mmv::fuzz

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
#include "sim/scene/scene.hpp"

namespace mmv::fuzz {
namespace {

const char* const kSource = "fuzz.yaml";

/// A scene error must start with fuzz.yaml:LINE:COL: (the contract's "file:line:col").
std::optional<std::string> judgeSceneError(const SceneError& e) {
  static const std::regex positioned(R"(^fuzz\.yaml:\d+:\d+: )");
  if (std::regex_search(e.what(), positioned)) return std::nullopt;
  return "scene error without fuzz.yaml:line:col: " + printable(e.what());
}

}  // namespace

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

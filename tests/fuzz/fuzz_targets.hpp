#pragma once
// The fuzz targets (tests/fuzz/README.md): what one input does to the scene reader and to
// `modes`, judged against the README's contract. Shared by the libFuzzer harnesses
// (scene_fuzzer.cpp, built by tests/fuzz/build.sh with clang) and by the suite's replay
// of the regression corpus (replay_test.cpp), so the corpus is judged the same way in
// both.
#include <exception>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace mmv::fuzz {

/// The scene reader on `text` as a file named fuzz.yaml. nullopt: the contract held (a
/// scene, or a SceneError that points at fuzz.yaml:line:col); else what broke it.
std::optional<std::string> readerTarget(const std::string& text);

/// `modes` (text and JSON) on what the reader accepts, at 2 segments per flexible link.
/// nullopt: the contract held (a result with every number finite, or a named error:
/// scene, numerical); else what broke it (another exception, a NaN or inf printed).
std::optional<std::string> modesTarget(const std::string& text);

/// The sweep spec reader (sim/scene/read_design_sweep.cpp) on `text` as fuzz.yaml, and its
/// points when there are few: a spec or a SceneError at fuzz.yaml:LINE:COL.
std::optional<std::string> specTarget(const std::string& text);

/// The UFF reader (sim/io/uff_read.hpp) on `text` as fuzz.uff: a file, or a SceneError
/// that starts "fuzz.uff:" (its line).
std::optional<std::string> uffTarget(const std::string& text);

/// Each line of `text` as a --set override of the embedded default scene: a scene, or
/// an error that names the override ("--set LINE: ...").
std::optional<std::string> setTarget(const std::string& text);

/// The run-directory reader (sim/io/run_dir.hpp): `text` split at its first line "@@"
/// into run.json and history.csv (states.csv a copy of it, scene.yaml the default
/// scene) in a private directory: a run, or an error that names the file it is about.
std::optional<std::string> runDirTarget(const std::string& text);

/// The judgement, exposed for its own tests. An exception: nullopt for a NumericalError
/// or a SceneError that starts with fuzz.yaml:LINE:COL:, else the breach.
std::optional<std::string> judgeException(std::exception_ptr error);
/// An output: the breach when the text prints a NaN or inf, or the JSON holds one.
std::optional<std::string> judgeOutput(const std::string& text, const nlohmann::ordered_json& json);

}  // namespace mmv::fuzz

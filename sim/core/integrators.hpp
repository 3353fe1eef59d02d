#pragma once
/// The one table of time integrators: every name the scene (`simulation.integrator`),
/// the command line (`--integrator`, `--integrators`) and the help text accept, with
/// what the time runs need to know about it. Plain data (sim/time/run_integrator.hpp
/// makes the integrator); it lives in core so that the scene reader checks names with
/// the key's line and column before any model is built.

#include <string>
#include <vector>

namespace mmv {

/// Which integrator: what sim/time/run_integrator.cpp makes, in one exhaustive switch
/// (a new entry that the factory does not handle is a compiler warning, an error in CI).
enum class IntegratorId {
  RkMerson, RkFeldberg, Rk3, Rk2, CPodes, Verlet, SemiExplicitEuler2, ExplicitEuler,  // Simbody's
  CvodeBdf, CvodeAdams, ArkodeErk, ArkodeDirk, Ida,                                  // SUNDIALS'
};

struct IntegratorInfo {
  enum class Family { Simbody, Sundials };
  const char* name;         ///< as written in scenes and on the command line.
  IntegratorId id;
  Family family;
  bool implicit;            ///< for stiff models (a Newton iteration per step).
  bool takes_absolute_tolerance;  ///< SUNDIALS' methods; Simbody's measure errors on the state's unit scale only.
  bool projects_closures;   ///< holds closed loops on their constraints (Simbody's projection, IDA's DAE).
  bool runs_modal_links;    ///< integrates links in modal coordinates (links[].modes): SUNDIALS' ODE methods.
  const char* description;  ///< one line for the help text and docs.
};

/// Every integrator, Simbody's first, in the order the help lists them.
const std::vector<IntegratorInfo>& integratorTable();
/// The entry named `name`, or nullptr.
const IntegratorInfo* findIntegrator(const std::string& name);
/// The entry of a name already checked (by the scene reader or a study); an unknown one
/// is an InternalError (a name that skipped the boundary).
const IntegratorInfo& integratorInfo(const std::string& name);
/// True for the SUNDIALS integrators (the plugin's).
bool isSundialsIntegrator(const std::string& name);
/// "rk_merson, rk_feldberg, ..." (every name), for messages.
std::string integratorNames();
/// Every integrator by family, as --integrator's help lists them: "rk_merson, ... (Simbody's);
/// cvode_bdf, ... (SUNDIALS)".
std::string integratorListing();
/// For an unknown name: " (did you mean 'x'?)" when one name is close, else "".
std::string integratorSuggestion(const std::string& name);

/// One allowed range per user quantity, stated once (docs/scene-format.md).
namespace limits {
/// Segments per flexible link: 1024 (4096 DOF) takes 30 s and 1.3 GB for `modes`; 4096
/// would need about 20 GB of dense matrices.
constexpr int kMaxSegments = 1024;
/// Rows of a time run (duration x sample rate): a million rows of history are about
/// 200 MB of CSV; beyond that a run is a mistake (a rate in Hz meant in kHz, a duration
/// in ms), not a plan.
constexpr double kMaxSamples = 1e6;
constexpr double kMinAccuracy = 1e-14;     ///< integrator relative accuracy, exclusive of 0 and 1.
/// A scene file: the shipped ones are a few kB; 16 MB is a mistake (a CSV or a binary).
constexpr long kMaxSceneBytes = 16L << 20;
/// A table profile (CSV): 10^6 samples at 60 bytes a row.
constexpr long kMaxProfileBytes = 64L << 20;
/// A measured UFF file (`correlate --measured`): 1000 FRFs of 4000 lines of 53 bytes.
constexpr long kMaxMeasuredBytes = 256L << 20;
/// A TAM file (`correlate --tam`, tam.mat): M, K over a few hundred channels and T over
/// the model's coordinates are a few MB; 64 MB is not a TAM.
constexpr long kMaxTamBytes = 64L << 20;
/// Measured nodes paired with the article by position (each costs a search along every link).
constexpr int kMaxMeasuredNodes = 2000;
}  // namespace limits

}  // namespace mmv

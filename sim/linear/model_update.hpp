#pragma once
/// Model updating (`mmvlab update`, docs/updating.md): the scene's uncertain values
/// adjusted so that its model reproduces a measured modal test.
///
///  - Parameters are scene keys as `--set` names them, each a plain number written in
///    the scene file, within bounds [lower, upper] that hold the nominal (the study
///    checks them: sim/app/update_study.hpp).
///  - Residuals: for each measured mode (a target) that a model mode shows at the
///    nominal, (f_model / f_test - 1) / frequency_sigma and, unless left out,
///    (1 - MAC) / mac_sigma. Which mode shows a target is found again in every model
///    (an article: correlate's pairing by MAC and frequency window against a measured
///    set; HAM-SAS: the features identified by shape, sim/hamsas/hamsas_modes.hpp), so a
///    mode that crosses another is followed by its shape; an evaluation where a tracked
///    target is shown by none is refused (the step is shrunk, never taken).
///  - The model at parameters p is the scene re-read from its text with the user's
///    patches and then KEY=p_k patches: every value checked by the reader as a --set is.
///  - Bounded Levenberg-Marquardt, identifiability and 95 % intervals:
///    sim/core/least_squares.hpp, with each parameter scaled by |nominal| (or by its
///    bounds' width when the nominal is 0). A combination is "not determined" when a
///    change of 100 % of the nominal along it moves the weighted residuals by less than
///    1 (the data's stated uncertainty).
///  - The updated scene is the file's own text with only the parameters' values changed,
///    each with a comment (nominal, updated, interval); it is read back and correlated
///    again: that correlation is the "after" reported, and it must reproduce the fit's
///    residuals (an internal error otherwise).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/least_squares.hpp"
#include "sim/scene/scene.hpp"
#include "sim/core/mode_number.hpp"

namespace mmv {

/// The scene as text with the patches it was read with: re-read at every evaluation.
struct SceneSource {
  std::string text, source;
  std::vector<std::string> sets;
  SceneFlags flags;
};

struct UpdateParameterSpec {
  std::string key;
  double nominal = 0, lower = 0, upper = 0;
  SceneValue where;  ///< the scalar in the file (sceneValueAt)
};

struct ModelUpdateOptions {
  double frequency_sigma = 0.01;  ///< relative
  double mac_sigma = 0.05;
  bool mac_residuals = true;
  double regularization = 0;      ///< residuals per unit relative change from the nominal
  int max_iterations = 30;
};

/// A measured mode the update fits: its name and frequency.
struct TestTarget {
  std::string label;  ///< "T3" (a measured set's third mode), "MGAS vertical" (a HAM-SAS feature)
  double hz = 0;
};
/// The model mode that shows a target: its number, frequency and shape match.
struct ModelMatch {
  ModeNumber model;
  double hz = 0, mac = 0;
};
/// Per target (in order), the mode of the model `scene` that shows it; nullopt: none.
/// Called at every evaluation: the matching is done again for each model.
using UpdateMatcher = std::function<std::vector<std::optional<ModelMatch>>(const Scene& scene)>;

struct UpdatedParameter {
  std::string key;
  int line = 0;
  double nominal = 0, lower = 0, upper = 0, updated = 0;
  double standard_error = 0, interval_half_width = 0;  ///< NaN: not determined, or no residual variance
  bool at_bound = false, determined = true;
};

struct UpdatePair {
  std::string test;  ///< the target's label
  double test_hz = 0;
  ModeNumber before_model, after_model;  ///< the model modes paired
  double before_hz = 0, after_hz = 0, before_mac = 0, after_mac = 0;
};

struct ModelUpdateResult {
  std::string scene, scene_source, measured;  ///< measured: where the targets came from
  std::vector<UpdatedParameter> parameters;
  std::vector<UpdatePair> pairs;      ///< the tracked test modes, before and after
  LeastSquaresResult fit;
  std::string updated_scene;          ///< the file's text with the updated values
  double rms_frequency_error_before = 0, rms_frequency_error_after = 0;  ///< relative, over the pairs
  ModelUpdateOptions options;
  std::vector<std::string> notes;     ///< targets left out (matched by no mode at the nominal)
};

/// The scene its text gives with parameter k at p(k) (SceneError as the reader's).
Scene sceneAt(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params, const Eigen::VectorXd& p);

/// Updates (see above) against `targets` as `match` finds them in each model. SceneError
/// when no target is matched at the nominal; NumericalError when the nominal model
/// cannot be solved.
ModelUpdateResult updateModel(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params,
                              const std::vector<TestTarget>& targets, const std::string& measured_source,
                              const UpdateMatcher& match, const ModelUpdateOptions& options);

/// The weighted residuals of a model's matches over the tracked targets: the relative
/// frequency errors, then (1 - MAC) when asked; nullopt when one is matched by none.
std::optional<Eigen::VectorXd> updateResiduals(const std::vector<TestTarget>& targets,
                                               const std::vector<std::optional<ModelMatch>>& matches,
                                               const std::vector<int>& tracked, const ModelUpdateOptions& options);

}  // namespace mmv

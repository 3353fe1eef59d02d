#pragma once
/// Model updating (`mmvlab update`, docs/updating.md): the scene's uncertain values
/// adjusted so that its model reproduces a measured modal test.
///
///  - Parameters are scene keys as `--set` names them, each a plain number written in
///    the scene file, within bounds [lower, upper] that hold the nominal (the study
///    checks them: sim/app/update_study.hpp).
///  - Residuals: for each test mode paired with a model mode at the nominal (correlate's
///    pairing, sim/linear/correlation.hpp: MAC and the frequency window),
///    (f_model / f_test - 1) / frequency_sigma and, unless left out,
///    (1 - MAC) / mac_sigma. The pairing is done again at every evaluation, so a model
///    mode that crosses another is followed by its shape; an evaluation where a tracked
///    test mode pairs with none is refused (the step is shrunk, never taken).
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
#include <optional>
#include <string>
#include <vector>

#include "sim/core/least_squares.hpp"
#include "sim/linear/correlation.hpp"
#include "sim/scene/scene.hpp"

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
  CorrelateOptions pairing;
  double frequency_sigma = 0.01;  ///< relative
  double mac_sigma = 0.05;
  bool mac_residuals = true;
  double regularization = 0;      ///< residuals per unit relative change from the nominal
  int max_iterations = 30;
};

struct UpdatedParameter {
  std::string key;
  int line = 0;
  double nominal = 0, lower = 0, upper = 0, updated = 0;
  double standard_error = 0, interval_half_width = 0;  ///< NaN: not determined, or no residual variance
  bool at_bound = false, determined = true;
};

struct UpdatePair {
  int test = 0;  ///< 0-based test mode
  double test_hz = 0;
  int before_model = 0, after_model = 0;  ///< 1-based model mode numbers paired
  double before_hz = 0, after_hz = 0, before_mac = 0, after_mac = 0;
};

struct ModelUpdateResult {
  std::string scene, measured;
  std::vector<UpdatedParameter> parameters;
  std::vector<UpdatePair> pairs;      ///< the tracked test modes, before and after
  LeastSquaresResult fit;
  std::string updated_scene;          ///< the file's text with the updated values
  double rms_frequency_error_before = 0, rms_frequency_error_after = 0;  ///< relative, over the pairs
  ModelUpdateOptions options;
  std::vector<std::string> notes;     ///< test modes left out (paired with none at the nominal)
};

/// The article the scene's text gives with parameter k at p(k) (SceneError as the reader's).
ArticleScene articleAt(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params, const Eigen::VectorXd& p);

/// Updates (see above). SceneError when no measured mode pairs with a model mode at the
/// nominal; NumericalError when the nominal model cannot be solved.
ModelUpdateResult updateModel(const SceneSource& scene, const std::vector<UpdateParameterSpec>& params,
                              const MeasuredSet& measured, const ModelUpdateOptions& options);

/// The relative frequency errors' weighted residuals of a correlation over the tracked
/// test modes (then the (1 - MAC) ones when asked); nullopt when one pairs with none.
std::optional<Eigen::VectorXd> updateResiduals(const CorrelationResult& c, const std::vector<int>& tracked,
                                               const ModelUpdateOptions& options);

}  // namespace mmv

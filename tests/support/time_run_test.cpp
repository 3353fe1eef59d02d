#include "support/time_run.hpp"

#include <gtest/gtest.h>

#include "sim/linear/state_space.hpp"

namespace mmv {
namespace {

// The linear model's transmissibility against the nonlinear Simbody model driven by
// the table: sine dwells (a stepped-sine test) at three frequencies below, between and
// above the first modes, table amplitude 1 mm, hinge dampers c = 0.02 s * k in both
// models. After 20 s the transient has decayed (the first mode's damping ratio is
// about 8 %), and the 1 mm motion keeps the nonlinearity negligible: measured
// differences 4e-7, 2e-5 and 1.4e-5 relative. Tolerance 1e-3.
TEST(TimeRun, SineDwellAgreesWithTheFrf) {
  const DampingSpec damping{DampingSpec::Kind::HingeViscous, 0.0, 0.0, 0.0, 0.02};
  for (double f : {0.5, 2.0, 6.0}) {
    ArticleScene s = loadDefaultScene();
    overrideSegments(s, 4);
    s.article.base.type = BaseType::Table;
    s.article.base.motion = TableMotion::sine(1e-3, f);
    s.damping = damping;
    SineDwellOptions o;
    o.point = "link3a.tip";
    const SineDwellResult run = runSineDwell(s, o);
    const LinearModel lm = buildLinearModel(s, {{"table_x", InputKind::BaseAcceleration, "", 0}},
                                            {{"tip_ax", OutputKind::Acceleration, "link3a.tip", 0, true}}, damping);
    const std::complex<double> frf = lm.second_order.response(2 * M_PI * f)(0, 0);
    EXPECT_LT(std::abs(run.transmissibility - frf), 1e-3 * std::abs(frf))
        << f << " Hz: time " << run.transmissibility << " frf " << frf;
  }
}

TEST(TimeRun, NeedsATableMotion) {
  SineDwellOptions o;
  o.point = "link1.tip";
  EXPECT_THROW(runSineDwell(loadDefaultScene(), o), SceneError);
}

}  // namespace
}  // namespace mmv

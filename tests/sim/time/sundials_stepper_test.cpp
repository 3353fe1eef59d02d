// The SUNDIALS plugin's failures (sim/time/sundials_plugin.cpp): a solver that stops says
// why in the error it returns, in SUNDIALS' own words and with what the right-hand side
// threw, and writes nothing to stderr (SUNDIALS' default printer did, in the middle of a
// command's output, for failures the command reports anyway).
#include "sim/time/external_stepper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace mmv {
namespace {

/// y' = -y, whose right-hand side throws once t passes `fail_after`.
class Decay : public ReducedCoordinates {
 public:
  explicit Decay(double fail_after) : fail_after_(fail_after) {}
  int size() const override { return 1; }
  void project(const SimTK::State&, double* y) const override { y[0] = 1.0; }
  void load(double t, const double* y, SimTK::State& s, double* ydot, bool) const override {
    if (t > fail_after_) throw std::runtime_error("a force element failed at t > 0.5");
    s.setTime(t);
    ydot[0] = -y[0];
  }

 private:
  double fail_after_;
};

struct StepperRun {
  bool ok = false;
  std::string error, stderr_text;
  double y_at_end = 0;
};

StepperRun decay(SundialsMethod method, double fail_after) {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter(system);
  const SimTK::State initial = system.realizeTopology();
  const Decay reduced(fail_after);
  auto stepper = makeSundialsStepper(system, method, 1e-8, 1e-10, &reduced);
  StepperRun r;
  ::testing::internal::CaptureStderr();
  r.ok = stepper->initialize(initial, r.error);
  if (r.ok) {
    stepper->setEndTime(1.0);
    r.ok = stepper->stepTo(1.0, r.error);
  }
  r.stderr_text = ::testing::internal::GetCapturedStderr();
  return r;
}

TEST(SundialsStepper, AFailedRightHandSideIsNamedInTheErrorAndNothingGoesToStderr) {
  // CVODE Adams included: its fixed-point iteration takes the failure for a convergence
  // failure and shrank the step without end (a hang) until the plugin gave it a minimum
  // step; it now stops with CV_CONV_FAILURE at that step.
  for (const SundialsMethod m : {SundialsMethod::CvodeBdf, SundialsMethod::ArkodeErk, SundialsMethod::ArkodeDirk,
                                 SundialsMethod::CvodeAdams}) {
    const StepperRun r = decay(m, 0.5);
    EXPECT_FALSE(r.ok) << static_cast<int>(m);
    EXPECT_NE(r.error.find(" stopped at t = "), std::string::npos) << r.error;
    EXPECT_NE(r.error.find("the right-hand side threw: a force element failed at t > 0.5"), std::string::npos) << r.error;
    const bool adams = m == SundialsMethod::CvodeAdams;
    EXPECT_NE(r.error.find(adams ? "CV_CONV_FAILURE" : "RHSFUNC_FAIL"), std::string::npos) << r.error;  // the flag's name
    // SUNDIALS' own sentence, from its error handler: the module and function that failed.
    EXPECT_TRUE(r.error.find("CVODE CVode: ") != std::string::npos || r.error.find("ARKODE ") != std::string::npos) << r.error;
    EXPECT_EQ(r.stderr_text, "") << static_cast<int>(m);
  }
}

TEST(SundialsStepper, ARunThatSucceedsSaysNothing) {
  for (const SundialsMethod m : {SundialsMethod::CvodeBdf, SundialsMethod::CvodeAdams, SundialsMethod::ArkodeErk, SundialsMethod::ArkodeDirk}) {
    const StepperRun r = decay(m, 2.0);
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.error, "");
    EXPECT_EQ(r.stderr_text, "");
  }
}

}  // namespace
}  // namespace mmv

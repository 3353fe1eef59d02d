// Rotational inputs and outputs of linear models (sim/linear/state_space.hpp): moments
// at points (moment:POINT:rx|ry|rz) and rotations about world axes (POINT:rx|ry|rz),
// against closed forms, reciprocity and the joint torque they must equal.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/linear/state_space.hpp"
#include "sim/model/article_builder.hpp"
#include "sim/model/stations.hpp"
#include "support/scenes.hpp"
#include "support/spatial_scenes.hpp"

namespace mmv {
namespace {

/// The static compliance (outputs x inputs): the response at 1e-4 rad/s, where the
/// first mode's (omega / omega_1)^2 is below 1e-10.
Eigen::MatrixXd staticCompliance(const LinearModel& lm) { return lm.full.response(1e-4).real(); }

// A clamped spatial cantilever under tip moments and a tip force, read as tip rotations
// and deflection. The discretized chain's springs in series give the continuum's
// compliances exactly where they are sums of h / (E I) over the hinges times a linear
// lever (the midpoint rule): twist L / (G J), bending out of the plane L / (E I_out);
// a moment about +y turns the tip about +y and moves it along -z by L^2 / (2 E I_out),
// which by reciprocity is the rotation about y per unit force along z (with the sign);
// torsion and bending do not couple on a straight link.
TEST(LinearRotations, ACantileversTipComplianceIsTheClosedForm) {
  const double E = 7e10, G = 2.6e10, L = 1.2, i_out = 4e-9, j = 2e-9;
  const ArticleScene s =
      testing::spatialCantilever(testing::explicitSection(2e-4, 1e-9, i_out, j), 2700, E, G, L, 12);
  const std::vector<InputSpec> in = {{"mx", InputKind::PointMoment, "link1.tip", 3},
                                     {"my", InputKind::PointMoment, "link1.tip", 4},
                                     {"fz", InputKind::PointForce, "link1.tip", 2}};
  const std::vector<OutputSpec> out = {{"rx", OutputKind::Displacement, "link1.tip", 3, false},
                                       {"ry", OutputKind::Displacement, "link1.tip", 4, false},
                                       {"z", OutputKind::Displacement, "link1.tip", 2, false}};
  const LinearModel lm = buildLinearModel(s, in, out, DampingSpec{});
  const Eigen::MatrixXd H = staticCompliance(lm);
  EXPECT_NEAR(H(0, 0), L / (G * j), 1e-9 * L / (G * j));
  EXPECT_NEAR(H(1, 1), L / (E * i_out), 1e-9 * L / (E * i_out));
  const double lever = L * L / (2 * E * i_out);
  EXPECT_NEAR(H(2, 1), -lever, 1e-9 * lever);
  EXPECT_NEAR(H(1, 2), -lever, 1e-9 * lever);  // Maxwell-Betti
  EXPECT_NEAR(H(0, 1), 0.0, 1e-12 * H(1, 1));
  EXPECT_NEAR(H(0, 2), 0.0, 1e-12 * H(1, 1));
  EXPECT_EQ(lm.full.output_units[0], "rad");
  EXPECT_EQ(lm.full.input_units[0], "N*m");
  // Rates and accelerations: i w and -w^2 times the rotation.
  const std::vector<OutputSpec> rates = {{"rx", OutputKind::Displacement, "link1.tip", 3, false},
                                         {"rx_vel", OutputKind::Velocity, "link1.tip", 3, false},
                                         {"rx_acc", OutputKind::Acceleration, "link1.tip", 3, false}};
  const LinearModel lr = buildLinearModel(s, {in[0]}, rates, DampingSpec{});
  const double w = 2 * M_PI * 7.0;
  const Eigen::MatrixXcd R = lr.full.response(w);
  EXPECT_LT(std::abs(R(1, 0) - std::complex<double>(0, w) * R(0, 0)), 1e-9 * std::abs(R(1, 0)));
  EXPECT_LT(std::abs(R(2, 0) + w * w * R(0, 0)), 1e-9 * std::abs(R(2, 0)));
  EXPECT_EQ(lr.full.output_units[1], "rad/s");
  EXPECT_EQ(lr.full.output_units[2], "rad/s^2");
}

// On the planar article a moment about z at the outboard root of a joint on the base is
// that joint's torque: J_w^T e_z is 1 on the joint's coordinate and 0 on the hinges
// outboard of it (a joint between two links would differ: its torque's reaction on the
// parent link cancels the parent's share). The root's rotation about z is the joint's
// angle: the same functions at every frequency.
TEST(LinearRotations, AMomentAtAJointsRootIsItsTorque) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  s.article.joints[0].hold = JointHold::Servo;
  s.article.joints[0].servo_stiffness = 3000;
  const std::vector<InputSpec> in = {{"torque", InputKind::JointTorque, "joint1", 0},
                                     {"moment", InputKind::PointMoment, "link1.root", 5}};
  const std::vector<OutputSpec> out = {{"tip", OutputKind::Acceleration, "link3a.tip", 1, false},
                                       {"rz", OutputKind::Displacement, "link1.root", 5, false}};
  const LinearModel lm = buildLinearModel(s, in, out, DampingSpec{});
  for (double f : {0.5, 3.3, 20.0}) {
    const Eigen::MatrixXcd H = lm.full.response(2 * M_PI * f);
    for (int o = 0; o < 2; ++o) EXPECT_LT(std::abs(H(o, 0) - H(o, 1)), 1e-12 * std::abs(H(o, 0))) << f << " Hz";
  }
  // The joint's angle per unit torque at 0.5 Hz, well below the first mode: about the
  // servo's compliance, once gravity's stiffness and the arm's flexibility are added.
  const double rz = std::abs(lm.full.response(2 * M_PI * 0.05)(1, 0));
  EXPECT_GT(rz, 0.5 / 3000);
  EXPECT_LT(rz, 2.0 / 3000);
}

// A station's rotation rows are its interpolated angular velocity's: J_w u equals
// angularVelocity() in a state where every hinge of a spatial link moves.
TEST(LinearRotations, AStationsRotationJacobianIsItsAngularVelocity) {
  const ArticleScene s = testing::spatialCantilever(testing::explicitSection(2e-4, 1e-9, 4e-9, 2e-9), 2700, 7e10,
                                                    2.6e10, 1.0, 5);
  const auto model = buildArticleModel(s);
  SimTK::State st = model->getReferenceState();
  const int n = model->getNumCoordinates();
  std::vector<int> all(n);
  Eigen::VectorXd u(n);
  for (int i = 0; i < n; ++i) {
    all[i] = i;
    st.updQ()[model->getQIndex(i)] = 0.1 * std::sin(1.0 + i);
    u[i] = 0.7 * std::cos(2.0 + i);
    st.updU()[model->getUIndex(i)] = u[i];
  }
  model->getSystem().realize(st, SimTK::Stage::Velocity);
  std::string error;
  for (const char* name : {"link1@0.37", "link1.tip"}) {
    const auto p = PointRef::resolve(*model, s.article, name, error);
    ASSERT_TRUE(p) << error;
    const Eigen::Vector3d w = p->rotationJacobian(st, all) * u;
    const SimTK::Vec3 w_ref = p->angularRate(st, 0) * p->localAxis(st, 0) + p->angularRate(st, 1) * p->localAxis(st, 1) +
                              p->angularRate(st, 2) * p->localAxis(st, 2);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(w[k], w_ref[k], 1e-12 * (1 + w.norm())) << name << " axis " << k;
  }
}

// The planar model refuses the axes that leave its plane (z, rx, ry), naming them.
TEST(LinearRotations, ThePlanarModelRefusesRotationsOutOfItsPlane) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 2);
  // The study refuses it by name before any model is built (study_options_cli_test:
  // frf --output l1.tip:rx); below it, an out-of-plane output is an invariant.
  EXPECT_THROW(
      buildLinearModel(s, defaultInputs(), {{"link1.tip:rx", OutputKind::Displacement, "link1.tip", 3, false}}, DampingSpec{}),
      InternalError);
  EXPECT_NO_THROW(
      buildLinearModel(s, defaultInputs(), {{"link1.tip:rz", OutputKind::Displacement, "link1.tip", 5, false}}, DampingSpec{}));
}

}  // namespace
}  // namespace mmv

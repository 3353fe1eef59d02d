// The unit of a scene key (sim/scene/key_units.hpp), by its dotted path or its CSV column
// name: a key ends in a known name after '.' or '_', or is it; nothing else matches.
#include <gtest/gtest.h>

#include "sim/scene/key_units.hpp"

namespace mmv {
namespace {

TEST(SceneKeyUnits, KeysTakeTheUnitOfTheirLastName) {
  EXPECT_EQ(sceneKeyUnit("links.link3.length"), "m");
  EXPECT_EQ(sceneKeyUnit("links_link3_length"), "m");
  EXPECT_EQ(sceneKeyUnit("sections.link3_rod.radius"), "m");
  EXPECT_EQ(sceneKeyUnit("materials.carbon_carbon.youngs_modulus"), "Pa");
  EXPECT_EQ(sceneKeyUnit("joints.joint2.torquer.mass"), "kg");
  EXPECT_EQ(sceneKeyUnit("joints_joint1_torque_capacity"), "N*m");
  EXPECT_EQ(sceneKeyUnit("joints.joint2.angle_deg"), "deg");
  EXPECT_EQ(sceneKeyUnit("joints.joint2.slew.max_rate_deg_s"), "deg/s");  // not "s" of a shorter name
  EXPECT_EQ(sceneKeyUnit("base.gimbal.ring_inertia"), "kg*m^2");
  EXPECT_EQ(sceneKeyUnit("length"), "m");
  // A name is matched whole: "strength" is not a length, "segments" has no unit.
  EXPECT_EQ(sceneKeyUnit("materials.m.strength"), "");
  EXPECT_EQ(sceneKeyUnit("materials.m.yield_strength"), "Pa");
  EXPECT_EQ(sceneKeyUnit("materials.m.ultimate_strength"), "Pa");
  EXPECT_EQ(sceneKeyUnit("sections.s.fibre_distance_out"), "m");
  EXPECT_EQ(sceneKeyUnit("links.link1.segments"), "");
  EXPECT_EQ(sceneKeyUnit("materials.m.poisson_ratio"), "");
  EXPECT_EQ(sceneKeyLabel("links_link3_length"), "links_link3_length (m)");
  EXPECT_EQ(sceneKeyLabel("links_link1_segments"), "links_link1_segments");
}

}  // namespace
}  // namespace mmv

#include "sim/io/finite_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mmv {
namespace {

TEST(FiniteCheck, FindsNaNAndInfPrintedAsWords) {
  EXPECT_EQ(firstNonFiniteLine("mode 1  1.3365 Hz\nmode 2  infinite-looking words are fine\n"), "");
  EXPECT_EQ(firstNonFiniteLine("a\n  span   inf\n"), "line 2: '  span   inf'");
  EXPECT_EQ(firstNonFiniteLine("f = -nan Hz"), "line 1: 'f = -nan Hz'");
  EXPECT_EQ(firstNonFiniteLine("x,NaN,3"), "line 1: 'x,NaN,3'");
  EXPECT_EQ(firstNonFiniteLine("+inf"), "line 1: '+inf'");
  EXPECT_EQ(firstNonFiniteLine("information, influence, nano, finance"), "");
}

TEST(FiniteCheck, FindsTheJsonPointerOfANonFiniteNumber) {
  nlohmann::ordered_json j;
  j["scene"] = "mmv";
  j["modes"] = {{{"f", 1.3}}, {{"f", 2.5}}};
  EXPECT_EQ(firstNonFiniteJson(j), "");
  j["modes"][1]["f"] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(firstNonFiniteJson(j), "/modes/1/f");
  EXPECT_EQ(firstNonFiniteJson(nlohmann::ordered_json(-INFINITY)), "/");
}

}  // namespace
}  // namespace mmv

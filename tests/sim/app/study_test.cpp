// The study layer's own helpers (sim/app/study.hpp).
#include "sim/app/study.hpp"

#include <gtest/gtest.h>

namespace mmv::app {
namespace {

// The one number parser of split options (--grid, --vary, --band): a whole finite number
// or nothing, never a prefix, NaN or an overflow to infinity.
TEST(Study, FiniteNumberTakesAWholeFiniteNumberOnly) {
  EXPECT_EQ(finiteNumber("2.5"), 2.5);
  EXPECT_EQ(finiteNumber("-1e-3"), -1e-3);
  EXPECT_EQ(finiteNumber("0"), 0.0);
  for (const char* bad : {"", "2.5x", "x", "nan", "inf", "-inf", "1e400", "1,5", " "})
    EXPECT_FALSE(finiteNumber(bad).has_value()) << "'" << bad << "'";
}

// A bound, and one past it, as the options' messages name them per front end.
TEST(Study, CheckRangeHoldsItsBoundsAndNamesTheOptionPerFrontEnd) {
  EXPECT_NO_THROW(checkRange(Front::Cli, "--modes", 500, 1, 500));
  EXPECT_NO_THROW(checkRange(Front::Cli, "--modes", 1, 1, 500));
  try {
    checkRange(Front::Python, "--mac-threshold", 1.01, 0, 1);
    FAIL() << "1.01 accepted";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("mac_threshold: ", 0), 0u) << e.what();
  }
  EXPECT_THROW(checkRange(Front::Cli, "--pair-distance", 0, 0, 1, /*open_low=*/true), UsageError);
}

}  // namespace
}  // namespace mmv::app

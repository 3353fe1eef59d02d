#include "sim/core/text.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace mmv {
namespace {

// What isValidUtf8 accepts is exactly what the JSON writer accepts (the campaign found
// an overlong C0 8E in a key that the first, lead-byte-only check let through).
TEST(Text, Utf8ValidityMatchesTheJsonWriter) {
  const std::vector<std::string> samples = {
      "plain", "caf\xC3\xA9", "\xE2\x82\xAC", "\xF0\x9D\x84\x9E", "\xEF\xBF\xBD",  // valid: e-acute, euro, G clef, U+FFFD
      "\xC0\x8E", "\xC1\xBF", "\xE0\x80\x80", "\xED\xA0\x80", "\xF4\x90\x80\x80",  // overlong, surrogate, > U+10FFFF
      "\xF5\x80\x80\x80", "\x80", "\xC3", "\xE2\x82", "a\xFF", "\xF0\x80\x80\x80"};
  for (const auto& s : samples) {
    bool json_ok = true;
    try {
      (void)nlohmann::json(s).dump();
    } catch (const nlohmann::json::exception&) {
      json_ok = false;
    }
    EXPECT_EQ(isValidUtf8(s), json_ok) << printable(s);
  }
}

TEST(Text, PrintableEscapesControlAndInvalidBytesOnly) {
  EXPECT_EQ(printable("caf\xC3\xA9"), "caf\xC3\xA9");
  EXPECT_EQ(printable("a\x1b[31mb"), "a\\x1B[31mb");
  EXPECT_EQ(printable("gravitd\xAD\xC0\x8Ey"), "gravitd\\xAD\\xC0\\x8Ey");
  EXPECT_TRUE(isValidUtf8(printable("\xFF\xFE\xC3(")));
}

}  // namespace
}  // namespace mmv

// ModeNumber (sim/core/mode_number.hpp): the one place a mode's number and its position
// in a frequency-ordered list are converted.
#include "sim/core/mode_number.hpp"

namespace mmv {
namespace {

TEST(ModeNumber, NumberAndIndexAreOneApart) {
  EXPECT_EQ(ModeNumber(1).index(), 0);
  EXPECT_EQ(ModeNumber::atIndex(0), ModeNumber(1));
  EXPECT_EQ(ModeNumber::atIndex(11).number(), 12);
  EXPECT_TRUE(ModeNumber(2) < ModeNumber(3));
  const std::vector<ModeNumber> m = modeNumbers({2, 4, 6});
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[1].index(), 3);
}

}  // namespace
}  // namespace mmv

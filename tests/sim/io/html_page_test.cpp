// The review page's pieces (sim/io/html_page.hpp, sim/io/review_report.hpp): base64
// against RFC 4648's vectors and an independent decoder, escaping, number alignment, the
// page's security policy, and the tables made from the studies' JSON.
#include <gtest/gtest.h>

#include <random>

#include "sim/io/html_page.hpp"
#include "sim/io/review_report.hpp"

namespace mmv {
namespace {

/// A decoder written apart from the encoder (a lookup of each character's position).
std::string decodeBase64(const std::string& s) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (const char c : s) {
    if (c == '=') break;
    const auto v = alphabet.find(c);
    if (v == std::string::npos) ADD_FAILURE() << "not base64: " << c;
    bits = bits << 6 | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>(bits >> count & 0xff);
    }
  }
  return out;
}

TEST(HtmlPage, Base64IsRfc4648) {
  const std::pair<const char*, const char*> vectors[] = {{"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},
                                                         {"foo", "Zm9v"},  {"foob", "Zm9vYg=="},  {"fooba", "Zm9vYmE="},
                                                         {"foobar", "Zm9vYmFy"}};
  for (const auto& [in, out] : vectors) EXPECT_EQ(html::base64(in), out) << in;
  std::mt19937 rng(7);
  for (int n = 0; n < 64; ++n) {
    std::string bytes(n * 7 + n % 3, '\0');
    for (auto& b : bytes) b = static_cast<char>(rng() & 0xff);
    const std::string enc = html::base64(bytes);
    EXPECT_EQ(enc.size() % 4, 0u);
    EXPECT_EQ(decodeBase64(enc), bytes) << n;
  }
}

TEST(HtmlPage, TextIsEscapedAndNumbersAligned) {
  EXPECT_EQ(html::escape("a<b & \"c\" 'd'>"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;");
  html::Table t;
  t.header = {"name", "value (Hz)", "mixed"};
  t.rows = {{"<x>", "1.5", "2"}, {"y", "-", "n/a"}, {"z", "3e-05 %", "4"}};
  t.row_classes = {"fail", "", "pass"};
  const std::string h = html::table(t);
  EXPECT_NE(h.find("<td>&lt;x&gt;</td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td class=\"num\">1.5</td>"), std::string::npos) << h;    // all numbers ("-" aside): right
  EXPECT_NE(h.find("<td class=\"num\">3e-05 %</td>"), std::string::npos) << h;
  EXPECT_NE(h.find("<td>2</td>"), std::string::npos) << h;                    // "n/a" in the column: left
  EXPECT_NE(h.find("<tr class=\"fail\">"), std::string::npos);
  EXPECT_NE(h.find("<tr><td>y</td>"), std::string::npos) << h;
}

TEST(HtmlPage, ThePageLoadsNothingAndLinksItsSections) {
  html::Page p;
  p.title = "T <1>";
  p.sections.push_back({"modes", "Modes", "<p>x</p>", {"within 1 %"}, {"mmvlab modes"}});
  const std::string h = html::page(p);
  EXPECT_EQ(h.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(h.find("default-src 'none'; img-src data:; style-src 'unsafe-inline'"), std::string::npos);
  EXPECT_EQ(h.find("<script"), std::string::npos);
  EXPECT_NE(h.find("<title>T &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(h.find("<a href=\"#modes\">Modes</a>"), std::string::npos);
  EXPECT_NE(h.find("<section id=\"modes\">"), std::string::npos);
  EXPECT_NE(h.find("<li>within 1 %</li>"), std::string::npos);
  EXPECT_NE(h.find("<code>mmvlab modes</code>"), std::string::npos);
  const std::string fig = html::pngFigure(std::string("\x89PNG", 4), "a\"b", "c");
  EXPECT_NE(fig.find("<figure><img alt=\"a&quot;b\" src=\"data:image/png;base64,iVBORw==\""), std::string::npos) << fig;
  // A PNG header 1600 pixels wide (0x640): the figure spans the grid's row; 1599 does not.
  std::string header("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0\x06\x40\0\0\x01\0", 24);
  EXPECT_EQ(html::pngFigure(header, "", "").rfind("<figure class=\"wide\">", 0), 0u);
  header[19] = '\x3f';
  EXPECT_EQ(html::pngFigure(header, "", "").rfind("<figure><img", 0), 0u);
}

// The estimate's modes are matched by number, not position: an estimate that lists its
// modes in another order (or leaves one out) must still put each error on its own mode.
TEST(ReviewReport, ModeTablePairsTheErrorEstimateByModeNumber) {
  const auto doc = nlohmann::ordered_json::parse(R"({
    "damping": {"model": "none"},
    "discretization_error": {"available": true, "segment_divisors": [4, 2], "modes": [
      {"number": 3, "estimated_relative_error": 0.03},
      {"number": 1, "estimated_relative_error": 0.01}]},
    "modes": [
      {"number": 1, "frequency_hz": 1.3364, "strain_energy_share_by_link": {"link1": 0.9, "link2": 0.1},
       "kinetic_energy_share": {"torquer": 0.6, "link1": 0.4}, "effective_mass_x_kg": 2, "effective_mass_y_kg": null,
       "geometric_stiffness_share": 0.05},
      {"number": 2, "frequency_hz": 3.2},
      {"number": 3, "frequency_hz": 3.34, "stable": false}]})");
  const html::Table t = modeTable(doc);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.header.size(), 8u);  // no damping column: the scene is undamped
  EXPECT_EQ(t.rows[0][2], "1 %");
  EXPECT_EQ(t.rows[1][2], "-");
  EXPECT_EQ(t.rows[2][2], "3 %");
  EXPECT_EQ(t.rows[0][3], "link1 (90 %)");
  EXPECT_EQ(t.rows[0][4], "torquer (60 %)");
  EXPECT_EQ(t.rows[0][6], "-");
  EXPECT_EQ(t.rows[0][7], "5");
  EXPECT_EQ(t.row_classes[2], "fail");  // an unstable mode stands out
  const auto acc = modesAccuracy(nlohmann::ordered_json::parse(
      R"({"discretization_error": {"available": false}, "checks": {"eigen_residual": 1e-12, "orthogonality_error": 2e-14},
          "damping": {"model": "none"}})"));
  ASSERT_EQ(acc.size(), 3u);
  EXPECT_NE(acc[0].find("No discretization estimate"), std::string::npos);
  EXPECT_NE(acc[2].find("no damping"), std::string::npos);
}

TEST(ReviewReport, CheckRowsAreClassedByVerdict) {
  const auto doc = nlohmann::ordered_json::parse(R"({"segments": 8, "not_checked": 1, "lines": [
      {"verdict": "FAIL", "group": "torquers", "requirement": "r", "demand": 191.1, "capacity": 150, "unit": "N*m",
       "margin_pct": -27.4, "note": "rigid links"},
      {"verdict": "n/a", "group": "g", "requirement": "r", "demand": 1, "capacity": null, "unit": "", "margin_pct": null,
       "note": ""},
      {"verdict": "advisory", "group": "table", "requirement": "r", "demand": 28, "capacity": 10, "unit": "Hz",
       "margin_pct": -180, "note": ""}]})");
  const html::Table t = checkTable(doc);
  EXPECT_EQ(t.row_classes, (std::vector<std::string>{"fail", "na", "advisory"}));
  EXPECT_EQ(t.rows[0][3], "191.1");
  EXPECT_EQ(t.rows[1][4], "-");
  EXPECT_EQ(t.rows[0][6], "-27.4");
  EXPECT_EQ(checkAccuracy(doc).size(), 2u);  // the basis, and the line without a capacity
  EXPECT_EQ(reportNumber(nlohmann::ordered_json(0.5), 100), "50");
  EXPECT_EQ(reportNumber(nlohmann::ordered_json(nullptr)), "-");
}

}  // namespace
}  // namespace mmv

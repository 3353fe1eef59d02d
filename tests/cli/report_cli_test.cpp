// mmvlab report: the review page and report.json. Its tables are the studies' JSON, so
// report.json must equal what check, modes, place-sensors and frf print on their own (the
// same numbers computed by another process); its options are refused at their bounds'
// other side; a HAM-SAS scene gets its own page (the isolator's parts). The page in a real browser:
// tests/readback/report_browser.sh.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

using Json = nlohmann::json;

/// Every number in `a` within `tol` (relative) of `b`, every other value equal, keys
/// named in `skip` (wall times) aside. Fails with the path of the first difference.
void expectSameJson(const Json& a, const Json& b, double tol, const std::string& path = "") {
  static const std::set<std::string> skip{"seconds", "time_s", "wall_time_s"};
  if (a.is_number() && b.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    EXPECT_LE(std::abs(x - y), tol * std::max(1.0, std::abs(y))) << path << ": " << x << " against " << y;
    return;
  }
  ASSERT_EQ(a.type(), b.type()) << path;
  if (a.is_object()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    for (const auto& [k, v] : a.items())
      if (!skip.count(k)) {
        ASSERT_TRUE(b.contains(k)) << path << "." << k;
        expectSameJson(v, b.at(k), tol, path + "." + k);
      }
  } else if (a.is_array()) {
    ASSERT_EQ(a.size(), b.size()) << path;
    for (std::size_t i = 0; i < a.size(); ++i) expectSameJson(a[i], b[i], tol, path + "[" + std::to_string(i) + "]");
  } else {
    EXPECT_EQ(a, b) << path;
  }
}

TEST_F(Cli, ReportHoldsWhatEachCommandPrintsOnItsOwn) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const fs::path out = dir_ / "review";
  const Result r = run("report " + scene + " --segments 4 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("check: FAIL"), std::string::npos) << r.out;  // the slew's joint 1 is over its capacity
  const Json doc = Json::parse(slurp(out / "report.json"));
  const std::string common = scene + " --segments 4 --json";
  const Result check = run("check " + common), modes = run("modes " + common),
               sensors = run("place-sensors " + common + " --below-hz 50 --count 8"), frf = run("frf " + common);
  ASSERT_EQ(check.code, 3) << check.err;  // its FAIL, as the page says
  for (const Result* c : {&modes, &sensors, &frf}) ASSERT_EQ(c->code, 0) << c->err;
  // Modes and placement are deterministic to the last bit; the FRF's peaks are refined in
  // parallel, and check's dynamic lines come from time runs: the same to round-off.
  expectSameJson(doc.at("check"), Json::parse(check.out), 1e-9, "check");
  expectSameJson(doc.at("modes"), Json::parse(modes.out), 0, "modes");
  expectSameJson(doc.at("placement"), Json::parse(sensors.out), 0, "placement");
  expectSameJson(doc.at("frf"), Json::parse(frf.out), 1e-9, "frf");
  // The page: one file, every figure inlined, nothing the browser would fetch.
  const std::string html = slurp(out / "report.html");
  EXPECT_EQ(doc.at("figures").get<int>(), 2 + 1 + 3 + 16);  // two views, the modes, the plan's three, a Bode plot per pair
  std::size_t images = 0;
  for (std::size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1)) {
    ++images;
    EXPECT_EQ(html.compare(html.find("src=\"", at), 27, "src=\"data:image/png;base64,"), 0) << html.substr(at, 80);
  }
  EXPECT_EQ(images, 22u);
  for (const char* remote : {"http:", "https:", "src=\"//", "href=\"//", "url("}) EXPECT_EQ(html.find(remote), std::string::npos) << remote;
  for (const char* id : {"article", "check", "strength", "modes", "sensors", "frf", "scene"})
    EXPECT_NE(html.find("<section id=\"" + std::string(id) + "\">"), std::string::npos) << id;
  // The strength section: each link's static peak as modes prints it, and check's run line.
  const std::string strength = html.substr(html.find("<section id=\"strength\">"), html.find("<section id=\"modes\">") - html.find("<section id=\"strength\">"));
  const Json modes_doc = Json::parse(modes.out);
  for (const auto& l : modes_doc.at("equilibrium").at("static_stress").at("links")) {
    char mpa[32];
    std::snprintf(mpa, sizeof mpa, "%.4g", 1e-6 * l.at("equivalent_pa").get<double>());
    EXPECT_NE(strength.find("<td>" + l.at("link").get<std::string>() + "</td>"), std::string::npos) << l;
    EXPECT_NE(strength.find(mpa), std::string::npos) << mpa << " " << strength.substr(0, 3000);
  }
  EXPECT_NE(strength.find("MPa (pass)"), std::string::npos);  // check's lines beside it
  // The scene's own text, escaped, and the commands that reproduce each part.
  EXPECT_NE(html.find("name: MMV article slewed on the table"), std::string::npos);
  EXPECT_NE(html.find("mmvlab place-sensors " + scene + " --segments 4 --below-hz 50 --count 8 --out sensors"), std::string::npos);
}

// HAM-SAS: the isolator's page. report.json equals modes, place-sensors (the modes below
// 5 Hz, 12 sensors: the report's defaults for an isolator) and frf run on their own, and
// the page holds the measured features, the transmissibility's goal and no check part.
TEST_F(Cli, ReportOnHamsasHoldsWhatEachCommandPrintsOnItsOwn) {
  const std::string scene = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string();
  const fs::path out = dir_ / "isolator";
  const Result r = run("report " + scene + " --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("measured features"), std::string::npos) << r.out;
  const Json doc = Json::parse(slurp(out / "report.json"));
  const Result modes = run("modes " + scene + " --json"), sensors = run("place-sensors " + scene + " --below-hz 5 --count 12 --json"),
               frf = run("frf " + scene + " --json");
  for (const Result* c : {&modes, &sensors, &frf}) ASSERT_EQ(c->code, 0) << c->err;
  EXPECT_FALSE(doc.contains("check"));
  expectSameJson(doc.at("modes"), Json::parse(modes.out), 0, "modes");
  expectSameJson(doc.at("placement"), Json::parse(sensors.out), 0, "placement");
  expectSameJson(doc.at("frf"), Json::parse(frf.out), 0, "frf");
  const std::string html = slurp(out / "report.html");
  for (const char* id : {"isolator", "modes", "sensors", "frf", "scene"})
    EXPECT_NE(html.find("<section id=\"" + std::string(id) + "\">"), std::string::npos) << id;
  EXPECT_EQ(html.find("<section id=\"check\">"), std::string::npos);
  for (const auto& f : doc.at("modes").at("features"))  // every measured feature in its table
    EXPECT_NE(html.find("<td>" + f.at("feature").get<std::string>() + "</td>"), std::string::npos) << f.at("feature");
  // The x transmissibility at 10 Hz as the tile says it, and its goal's verdict.
  const double x10 = doc.at("frf").at("at_10_hz_db").at(0).at(0).get<double>();
  char tile[64];
  std::snprintf(tile, sizeof tile, "x at 10 Hz: %.1f dB", x10);
  EXPECT_NE(html.find(tile), std::string::npos) << tile;
  EXPECT_NE(html.find(x10 <= -80 ? "meets 80 dB" : x10 <= -70 ? "meets 70 dB" : "misses 70 dB"), std::string::npos);
  std::size_t images = 0;
  for (std::size_t at = html.find("<img "); at != std::string::npos; at = html.find("<img ", at + 1)) ++images;
  EXPECT_EQ(images, static_cast<std::size_t>(doc.at("figures").get<int>()));
  EXPECT_GE(images, 2u + 1 + 2 + 5);  // two views, the modes, the plan's, the transmissibility's five
}

TEST_F(Cli, ReportRefusesWhatItCannotDo) {
  const fs::path out = dir_ / "r";
  Result r = run("report");
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  // HAM-SAS: the plan's count past the isolator's candidates, named as the report's.
  r = run("report " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() + " --sensors 100000 --out " + out.string());
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("the sensor plan (report --sensors 100000, modes below 5 Hz)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // --modes 1 .. 500 (the bound and one past it), --sensors within the candidates.
  for (const char* bad : {"--modes 0", "--modes 501", "--sensors 0", "--band 50:1"}) {
    r = run(std::string("report --segments 2 ") + bad + " --out " + out.string());
    EXPECT_EQ(r.code, 64) << bad << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out)) << bad;
  }
  r = run("report --segments 2 --sensors 1000 --out " + out.string());
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("the sensor plan (report --sensors 1000)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  r = run("report --segments 2 --sensors 1 --out " + out.string());  // fewer than the 8 target modes
  EXPECT_EQ(r.code, 64);
  EXPECT_NE(r.err.find("needs at least one measured direction per target mode"), std::string::npos) << r.err;
  r = run("report --segments 2 --modes 500 --out " + out.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const Json doc = Json::parse(slurp(out / "report.json"));
  EXPECT_EQ(doc.at("modes").at("modes").size(), 8u);  // 2 segments per link have 8 modes: 500 asks for all
  EXPECT_EQ(doc.at("placement").at("chosen").size(), 8u);
  // A second run into the same directory refuses to replace the page without --force.
  r = run("report --segments 2 --out " + out.string());
  EXPECT_EQ(r.code, 73);
  EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace mmv::cli_testing

// The bounds on counts a user controls (docs/reliability.md, "Bounds"): each at the
// bound and one past it, the refusal before anything is allocated or drawn.
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>

#include "sim/modes/config_sweep.hpp"
#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

/// A PNG's width and height from its IHDR chunk.
std::pair<std::uint32_t, std::uint32_t> pngSize(const fs::path& p) {
  const std::string s = slurp(p);
  if (s.size() < 24) return {0, 0};
  auto be = [&](std::size_t at) {
    return (std::uint32_t(std::uint8_t(s[at])) << 24) | (std::uint32_t(std::uint8_t(s[at + 1])) << 16) |
           (std::uint32_t(std::uint8_t(s[at + 2])) << 8) | std::uint32_t(std::uint8_t(s[at + 3]));
  };
  return {be(16), be(20)};
}

// The documented maximum, 8192 x 8192, segfaulted inside OSMesa after 2.5 GB (it was
// drawn at 3x: 24576 samples a side). It is drawn now (supersampling lowered to keep
// the buffer at 8192 a side), and 8193 is refused.
TEST_F(Cli, RenderDrawsTheDocumentedMaximumSizeAndRefusesOnePast) {
  const fs::path big = dir_ / "big.png";
  const Result r = run("render --size 8192x8192 --out " + big.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(pngSize(big), std::make_pair(8192u, 8192u));
  for (const char* past : {"8193x16", "16x8193"}) {
    const Result p = run(std::string("render --size ") + past + " --out " + (dir_ / "past.png").string());
    EXPECT_EQ(p.code, 64) << past;
    EXPECT_NE(p.err.find("16 to 8192 each"), std::string::npos) << p.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "past.png"));
}

// MPEG-4 part 2 codes 13-bit dimensions: 8192 failed inside the encoder with a message
// naming our temporary file; it is refused up front, 8191 is written.
TEST_F(Cli, AnMp4IsAtMost8191PixelsASide) {
  const Result ok = run("render --mode 1 --size 8191x16 --out " + (dir_ / "ok.mp4").string());
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_GT(fs::file_size(dir_ / "ok.mp4"), 1000u);
  const Result past = run("render --mode 1 --size 8192x16 --out " + (dir_ / "past.mp4").string());
  EXPECT_EQ(past.code, 64);
  EXPECT_NE(past.err.find("--size 8192x16: an .mp4 video (MPEG-4 part 2) is at most 8191 pixels a side"), std::string::npos) << past.err;
  EXPECT_FALSE(fs::exists(dir_ / "past.mp4"));
}

// A contact sheet is one image: at most 8192 x 8192 pixels in all (12 modes at
// 8192 x 8192 took 5.7 GB).
TEST_F(Cli, AContactSheetIsAtMost8192By8192PixelsInAll) {
  const fs::path sheet = dir_ / "sheet.png";
  const Result at = run("render --mode 1-2 --size 8192x4096 --out " + sheet.string());
  ASSERT_EQ(at.code, 0) << at.err;
  EXPECT_EQ(pngSize(sheet), std::make_pair(16384u, 4096u));
  const Result past = run("render --mode 1-3 --size 8192x4096 --out " + (dir_ / "past.png").string());
  EXPECT_EQ(past.code, 64);
  EXPECT_NE(past.err.find("a contact sheet of 3 frames is 101 Mpixel, above the limit of 67.1 Mpixel"), std::string::npos) << past.err;
  EXPECT_FALSE(fs::exists(dir_ / "past.png"));
}

// sweep-config's grid: 2000 values an axis, counted before any is made (a step of
// 1e-10 deg over 20 deg made 2e11 values: bad_alloc, exit 70).
TEST(Bounds, AGridAxisCountsItsValuesWithoutMakingThem) {
  GridAxis at{"joint1", 0, 1999, 1}, past{"joint1", 0, 2000, 1}, tiny{"joint1", 0, 20, 1e-10};
  EXPECT_EQ(at.count(), 2000);
  EXPECT_EQ(at.values().size(), 2000u);
  EXPECT_EQ(past.count(), 2001);
  EXPECT_DOUBLE_EQ(tiny.count(), 2e11 + 1);
  GridAxis fine{"joint1", 0, 1, 0.1};  // 1/0.1 in floating point: 11 values, the last 1.0
  EXPECT_EQ(fine.values().size(), 11u);
  EXPECT_NEAR(fine.values().back(), 1.0, 1e-12);
}

TEST_F(Cli, SweepConfigRefusesAGridAxisPastItsBoundBeforeMakingIt) {
  for (const char* grid : {"joint1:0:2000:1", "joint1:0:20:1e-10"}) {
    const Result r = run(std::string("sweep-config --grid ") + grid + " --out " + (dir_ / "s").string());
    EXPECT_EQ(r.code, 64) << grid << r.err;
    EXPECT_NE(r.err.find("values on one axis, above the limit of 2000"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "s"));
}

// render runs again with glibc's malloc on transparent huge pages (sim/cli/huge_pages.hpp:
// the frame buffers' page faults were a third of its whole process): the frame is the
// same, byte for byte, with the re-execution, without it (MMVLAB_NO_HUGE_PAGES), and when
// the user's own GLIBC_TUNABLES is extended, and a frame within the budget stays there.
// A rectangular tube's wall of 1e-20 m, a number the reader accepts, made E*I exactly 0
// (the second moment's closed form cancelled) and modes, check and frf exit 70 ("internal
// error: discretizeLink ..."; issue 68). The section now has its (tiny) stiffness: the
// verbs compute or fail with a named error, never an internal one.
TEST_F(Cli, AFilmThinTubeWallIsNeverAnInternalError) {
  for (const char* verb : {"modes", "check", "frf"}) {
    const Result r = run(std::string(verb) + " --segments 2 --set sections.link1_tube.t=1e-20");
    EXPECT_NE(r.code, 70) << verb << "\n" << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << verb << "\n" << r.err;
    // check may FAIL such a wall (exit 3): an answer, not an error.
    EXPECT_TRUE(r.code == 0 || r.code == 1 || r.code == 65 || (r.code == 3 && std::string(verb) == "check"))
        << verb << ": exit " << r.code << "\n" << r.err;
  }
}

// Very stiff joints hold (issue 68): a servo of 1e8 N*m/rad and more "failed" its
// equilibrium at a residual of 8e-9 N*m, the round-off of its own stiffness, and the
// message blamed buckling. At every stiffness the servo now holds, and its sag is the
// torque it carries over its stiffness, computed two ways (the equilibrium's angle
// against the commanded one, and torque / k).
TEST_F(Cli, AVeryStiffServoHoldsItsEquilibrium) {
  for (const char* k : {"1e6", "1e8", "1e9", "1e10"}) {
    const Result r = run(std::string("modes --segments 4 --modes 1 --json --set joints.joint2.hold=servo --set "
                                     "joints.joint2.servo_stiffness=") + k);
    ASSERT_EQ(r.code, 0) << k << "\n" << r.err;
    EXPECT_EQ(r.err.find("buckl"), std::string::npos) << k << "\n" << r.err;
    const auto e = nlohmann::json::parse(r.out).at("equilibrium");
    EXPECT_TRUE(e.at("converged").get<bool>()) << k;
    const auto& j = e.at("joints").at(1);
    ASSERT_EQ(j.at("name"), "joint2");
    const double sag_deg = j.at("commanded_angle_deg").get<double>() - j.at("equilibrium_angle_deg").get<double>();
    const double expected_deg = j.at("torque_n_m").get<double>() / std::stod(k) * 180 / M_PI;
    EXPECT_NEAR(std::abs(sag_deg), std::abs(expected_deg), 1e-4 * std::abs(expected_deg) + 1e-12) << k;
  }
}

// HAM-SAS's optical table of 1e10 m, a number the reader accepts, made Simbody's
// integrator fail to start ("Matrix is singular") and simulate and trade exit 70 (issue
// 68): a numerical failure of the model, exit 1, named.
TEST_F(Cli, AnIsolatorTheIntegratorCannotStartIsANumericalFailure) {
  const std::string scene = std::string(MMVLAB_SOURCE_DIR) + "/scenes/hamsas.yaml";
  for (const std::string args : {"simulate " + scene + " --duration 0.01", "trade " + scene + " --duration 0.01 --integrators rk_merson --accuracies 1e-3"}) {
    const Result r = run(args + " --set hamsas.ot_size_x=1e10");
    EXPECT_NE(r.code, 70) << args << "\n" << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << args << "\n" << r.err;
    if (r.code == 1) EXPECT_NE(r.err.find("could not start"), std::string::npos) << args << "\n" << r.err;
  }
}

TEST_F(Cli, RenderOnHugePagesDrawsTheSameFrame) {
  const fs::path a = dir_ / "huge.png", b = dir_ / "small.png", c = dir_ / "user.png";
  ASSERT_EQ(run("render --size 640x360 --out " + a.string()).code, 0);
  ASSERT_EQ(run("render --size 640x360 --out " + b.string(), "MMVLAB_NO_HUGE_PAGES=1 ").code, 0);
  ASSERT_EQ(run("render --size 640x360 --out " + c.string(), "GLIBC_TUNABLES=glibc.malloc.trim_threshold=1048576 ").code, 0);
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_EQ(slurp(a), slurp(c));
  EXPECT_FALSE(slurp(a).empty());
}

}  // namespace
}  // namespace mmv::cli_testing

// mmvlab render --history: a simulate run redrawn as a video or a still, with sensor
// traces, and the mistakes a user makes with it refused without a partial file.
#include <opencv2/videoio.hpp>

#include "support/cli.hpp"

namespace mmv::cli_testing {
namespace {

TEST_F(Cli, RenderHistoryDrawsASimulateRun) {
  ::unsetenv("DISPLAY");
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const fs::path run_dir = dir_ / "run";
  const Result sim = run("simulate " + slew + " --segments 2 --duration 0.5 --sample-rate 250 --out " + run_dir.string());
  ASSERT_EQ(sim.code, 0) << sim.err;
  for (const char* f : {"history.csv", "states.csv", "scene.yaml", "run.json", "summary.json"})
    EXPECT_TRUE(fs::exists(run_dir / f)) << f;
  // A video: 0.5 s at 30 frames/s and speed 1 is 16 frames; at speed 0.5, 31.
  const fs::path video = dir_ / "slew.avi";
  const Result v = run("render --history " + run_dir.string() + " --traces enc1,acc_link2_tip --size 320x240 --out " +
                       video.string());
  ASSERT_EQ(v.code, 0) << v.err;
  cv::VideoCapture in(video.string());
  ASSERT_TRUE(in.isOpened());
  EXPECT_EQ(static_cast<int>(in.get(cv::CAP_PROP_FRAME_COUNT)), 16);
  EXPECT_EQ(static_cast<int>(in.get(cv::CAP_PROP_FRAME_WIDTH)), 320);
  const fs::path slow = dir_ / "slow.avi";
  const Result s = run("render --history " + run_dir.string() + " --speed 0.5 --size 160x120 --out " + slow.string());
  ASSERT_EQ(s.code, 0) << s.err;  // stderr too: a sanitizer's report or the error that made it fail
  EXPECT_EQ(static_cast<int>(cv::VideoCapture(slow.string()).get(cv::CAP_PROP_FRAME_COUNT)), 31);
  // A still at a time; the same run and time give the same pixels.
  const fs::path a = dir_ / "a.png", b = dir_ / "b.png", end = dir_ / "end.png";
  for (const fs::path& still : {a, b}) {
    const Result r = run("render --history " + run_dir.string() + " --at 0.3 --size 320x240 --out " + still.string());
    ASSERT_EQ(r.code, 0) << r.err;
  }
  EXPECT_TRUE(isPng(a));
  EXPECT_EQ(slurp(a), slurp(b));
  const Result e = run("render --history " + run_dir.string() + " --size 320x240 --out " + end.string());
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_NE(slurp(a), slurp(end));  // the slew moved the article between 0.3 s and the end
}

// --set on the command line: recorded with the run, applied again when it is redrawn.
TEST_F(Cli, SetOverridesAreRecordedAndReapplied) {
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const fs::path run_dir = dir_ / "run";
  const Result sim = run("simulate " + slew + " --segments 2 --duration 0.2 --sample-rate 250 --set links.link1.length=2.0 "
                         "--set damping.hinge_beta=0.004 --json --out " + run_dir.string());
  ASSERT_EQ(sim.code, 0) << sim.err;
  EXPECT_NE(slurp(run_dir / "run.json").find("\"links.link1.length=2.0\""), std::string::npos);
  EXPECT_EQ(run("render --history " + run_dir.string() + " --size 160x120 --out " + (dir_ / "a.png").string()).code, 0);
  const Result text = run("modes --modes 1 --set links.link1.length=2.0");
  EXPECT_NE(text.out.find("(scene: <default scene> --set links.link1.length=2.0)"), std::string::npos) << text.out;
  const Result bad = run("modes --set links.link1.length=-1");
  EXPECT_EQ(bad.code, 65);
  EXPECT_NE(bad.err.find("--set links.link1.length=-1: links[0].length must be > 0 m (got -1)"), std::string::npos) << bad.err;
  EXPECT_EQ(run("modes --set links.link1.length").code, 64);
  // Runs that would never end or fill the disk are refused before they start.
  const Result huge = run("simulate --sample-rate 1e9 --duration 1e6");
  EXPECT_EQ(huge.code, 64);
  EXPECT_NE(huge.err.find("above the limit of 1000000"), std::string::npos) << huge.err;
  EXPECT_EQ(run("simulate --set simulation.sample_rate_hz=1e9").code, 65);
  EXPECT_EQ(run("trade --duration 1e6").code, 64);
  const Result isolator = run("modes " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                              " --set hamsas.counterweight_mass=3.4 --json");
  EXPECT_EQ(isolator.code, 0) << isolator.err;
}

TEST_F(Cli, RenderHistoryRefusesWhatItCannotDraw) {
  const std::string slew = (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv-slew.yaml").string();
  const fs::path run_dir = dir_ / "run", out = dir_ / "x.png";
  ASSERT_EQ(run("simulate " + slew + " --segments 2 --duration 0.2 --sample-rate 250 --out " + run_dir.string()).code, 0);
  const Result missing = run("render --history " + (dir_ / "nothing").string() + " --out " + out.string());
  EXPECT_EQ(missing.code, 66);
  EXPECT_NE(missing.err.find("not a directory"), std::string::npos) << missing.err;
  const Result other = run("render " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "mmv.yaml").string() + " --history " +
                           run_dir.string() + " --out " + out.string());
  EXPECT_EQ(other.code, 65);  // another scene's model
  EXPECT_NE(other.err.find("render a run with the scene and segments it was made with"), std::string::npos) << other.err;
  const Result trace = run("render --history " + run_dir.string() + " --traces acc9 --out " + out.string());
  EXPECT_EQ(trace.code, 64);
  EXPECT_NE(trace.err.find("no sensor or column 'acc9'"), std::string::npos) << trace.err;
  EXPECT_EQ(run("render --history " + run_dir.string() + " --at 5 --out " + out.string()).code, 64);
  // 0.2 s at 240 frames/s slowed 1000 times is 48,001 frames: above the 20,000 a video may have.
  const Result long_video = run("render --history " + run_dir.string() + " --fps 240 --speed 0.001 --out " +
                                (dir_ / "long.mp4").string());
  EXPECT_EQ(long_video.code, 64);
  EXPECT_NE(long_video.err.find("(limit 20000)"), std::string::npos) << long_video.err;
  EXPECT_FALSE(fs::exists(dir_ / "long.mp4"));
  EXPECT_EQ(run("render --history " + run_dir.string() + " --mode 1 --out " + out.string()).code, 64);
  EXPECT_EQ(run("render --history " + run_dir.string() + " --segments 4 --out " + out.string()).code, 64);
  EXPECT_EQ(run("render --traces enc1 --out " + out.string()).code, 64);
  // The run's segments reach the model through the scene reader as the run's own
  // --segments did: a record edited past the limit is a data error naming run.json.
  {
    const fs::path edited = dir_ / "edited";
    fs::copy(run_dir, edited, fs::copy_options::recursive);
    std::string record = slurp(edited / "run.json");
    const std::string key = "\"segments_override\": 2";
    ASSERT_NE(record.find(key), std::string::npos) << record;
    record.replace(record.find(key), key.size(), "\"segments_override\": 5000");
    std::ofstream(edited / "run.json") << record;
    const Result r = run("render --history " + edited.string() + " --out " + out.string());
    EXPECT_EQ(r.code, 65);
    EXPECT_NE(r.err.find("run.json: segments_override 5000: links[0].segments must be an integer from 1 to"),
              std::string::npos)
        << r.err;
  }
  // A HAM-SAS run is redrawn too, each body moved by its recorded motion; another
  // isolator's bodies are refused.
  const fs::path isolator_run = dir_ / "isolator", isolator_png = dir_ / "isolator.png";
  ASSERT_EQ(run("simulate " + (fs::path(MMVLAB_SOURCE_DIR) / "scenes" / "hamsas.yaml").string() +
                " --duration 0.1 --sample-rate 100 --out " + isolator_run.string()).code, 0);
  const Result isolator = run("render --history " + isolator_run.string() + " --traces optical_table_x_m --size 320x240 --out " +
                              isolator_png.string());
  EXPECT_EQ(isolator.code, 0) << isolator.err;
  EXPECT_TRUE(isPng(isolator_png));
  const Result mixed = run("render " + slew + " --history " + isolator_run.string() + " --out " + out.string());
  EXPECT_EQ(mixed.code, 65) << mixed.err;
  // A damaged states.csv is named at its line.
  std::ofstream(run_dir / "states.csv", std::ios::app) << "0.1,oops\n";
  const Result bad = run("render --history " + run_dir.string() + " --out " + out.string());
  EXPECT_EQ(bad.code, 65);
  EXPECT_NE(bad.err.find("states.csv:"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(out));
  for (const auto& e : fs::directory_iterator(dir_)) EXPECT_EQ(e.path().filename().string().rfind(".mmvlab-", 0), std::string::npos);
}

}  // namespace
}  // namespace mmv::cli_testing

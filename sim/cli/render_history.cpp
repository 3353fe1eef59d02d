// mmvlab render --history RUN_DIR: frames of a `simulate` run (a slew, a table
// excitation; HAM-SAS ground shaking) redrawn from its recorded coordinates
// (RUN_DIR/states.csv) on the model of the run's own scene copy and segments
// (RUN_DIR/scene.yaml, run.json), with an optional panel of chosen history.csv columns
// (sensor signals, torques, tips) beside it.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <memory>

#include "facility/table_programs.hpp"
#include "renders/layout.hpp"
#include "sim/cli/commands.hpp"
#include "sim/core/files.hpp"
#include "sim/core/progress.hpp"
#include "sim/cli/render_common.hpp"
#include "sim/core/text.hpp"
#include "sim/view/article_drawing.hpp"
#include "sim/view/hamsas_drawing.hpp"
#include "sim/view/run_pose.hpp"
#include "sim/io/output_dir.hpp"
#include "sim/io/run_dir.hpp"
#include "sim/io/vtk_export.hpp"
#include "sim/model/article_builder.hpp"

namespace mmv::cli {
namespace {

namespace fs = std::filesystem;

constexpr int kMaxFrames = 20000;  ///< about 11 minutes at 30 frames/s.

/// A column as a reader of the video reads it: angles in degrees (an encoder's rad, the
/// history's own unit, was against a scene written in degrees), with its unit in the name,
/// and its limit: a sensor's range, a torquer's capacity, the table's stroke.
render::Trace traceOf(const RunDir& run, std::size_t col) {
  const std::string& column = run.history.columns[col];
  auto ends = [&](const std::string& tail) {
    return column.size() > tail.size() && column.compare(column.size() - tail.size(), tail.size(), tail) == 0;
  };
  struct Unit {
    const char* suffix;
    const char* shown;
    double scale;
  };
  static const Unit kUnits[] = {{"_rad_per_s", "deg/s", 180 / M_PI}, {"_rad", "deg", 180 / M_PI}, {"_m_per_s2", "m/s^2", 1},
                                {"_n_m", "N*m", 1}, {"_m_per_m", "microstrain", 1e6}, {"_deg", "deg", 1}, {"_n", "N", 1},
                                {"_m", "cm", 100}};
  render::Trace tr;
  double scale = 1;
  tr.name = column;
  for (const auto& u : kUnits)
    if (ends(u.suffix)) {
      tr.name = column.substr(0, column.size() - std::strlen(u.suffix)) + " (" + u.shown + ")";
      scale = u.scale;
      break;
    }
  for (const auto& row : run.history.rows) {
    tr.t.push_back(row[0]);
    tr.v.push_back(scale * row[col]);
  }
  for (const auto& sensor : run.scene.sensors)  // its instrument's range
    if (column.rfind(csvColumnName(sensor.name) + "_", 0) == 0)
      for (const auto& ins : run.scene.instruments)
        if (ins.name == (sensor.instrument.empty() ? sensor.type : sensor.instrument)) tr.limit = scale * ins.spec.range, tr.limit_label = "range";
  for (const auto& j : run.scene.article.joints)
    if (column == csvColumnName(j.name) + "_torque_n_m" && j.torque_capacity > 0) tr.limit = j.torque_capacity, tr.limit_label = "capacity";
  if (column == "table_x_m") tr.limit = 100 * facility::TableSpec{}.stroke, tr.limit_label = "stroke";
  return tr;
}

/// --traces: a history.csv column by its name, or a sensor's column by the sensor's name.
std::vector<render::Trace> tracesFor(const RunDir& run, const std::vector<std::string>& names) {
  std::vector<render::Trace> out;
  for (const auto& name : names) {
    int col = run.history.column(csvColumnName(name));  // the CSV's names (sim/core/text.hpp)
    for (const auto& s : run.scene.sensors)
      if (col < 0 && s.name == name)
        for (std::size_t c = 0; c < run.history.columns.size(); ++c)
          if (run.history.columns[c].rfind(csvColumnName(name) + "_", 0) == 0) col = static_cast<int>(c);
    if (col <= 0) {
      std::string known;
      for (const auto& s : run.scene.sensors) known += s.name + ", ";
      for (std::size_t c = 1; c < run.history.columns.size(); ++c) known += run.history.columns[c] + (c + 1 < run.history.columns.size() ? ", " : "");
      throw UsageError("--traces: no sensor or column '" + name + "' in " + run.dir + "/history.csv (known: " + known + ")");
    }
    out.push_back(traceOf(run, static_cast<std::size_t>(col)));
  }
  return out;
}

/// The drawing of a run at time t, whatever kind of scene it is.
using DrawAt = std::function<DrawList(double t)>;

/// An article run: its model rebuilt, its coordinates set at each time.
DrawAt articleFrames(const RunDir& run, std::shared_ptr<Model>& model) {
  model = buildArticleModel(run.scene, ModelUse::TimeRun);
  checkRunModel(run, *model);
  auto state = std::make_shared<SimTK::State>(model->getReferenceState());
  return [&run, model, state](double t) {
    setRunPose(rowAt(run.states, t), t, *model, *state);  // between the samples around t
    DrawList d = drawArticle(run.scene, *model, *state);
    d.title += strf("  t = %.3f s", t);
    return d;
  };
}

/// A HAM-SAS run: each body moved by its recorded motion, magnified so the largest
/// translation over the run is 10 % of the isolator's extent (its motions are microns).
/// The isolator's bodies of `run`'s scene, checked against the run's states.csv.
std::shared_ptr<HamsasModes> isolatorOfRun(const RunDir& run) {
  auto h = std::make_shared<HamsasModes>(analyseHamsas(run.isolator->isolator));
  std::vector<std::string> want{"time_s"};
  for (const auto& body : h->model.bodies)
    for (const char* q : {"_x_m", "_y_m", "_z_m", "_rx_rad", "_ry_rad", "_rz_rad"}) want.push_back(csvColumnName(body.name + q));
  if (want != run.states.columns)
    throw SceneError(run.dir + "/states.csv: the run's columns are not the bodies of " + run.isolator->source +
                     ": render a run with the scene it was made with");
  return h;
}

/// Every body's recorded motion at t (between the samples around it).
std::vector<BodyMotion> isolatorMotionAt(const RunDir& run, std::size_t bodies, double t) {
  const std::vector<double> row = rowAt(run.states, t);
  std::vector<BodyMotion> motion(bodies);
  for (std::size_t b = 0; b < bodies; ++b) motion[b] = Eigen::Map<const BodyMotion>(row.data() + 1 + 6 * b);
  return motion;
}

DrawAt isolatorFrames(const RunDir& run, std::shared_ptr<HamsasModes>& h) {
  h = isolatorOfRun(run);
  const std::size_t bodies = h->model.bodies.size();
  double peak = 0;
  for (const auto& row : run.states.rows)
    for (std::size_t b = 0; b < bodies; ++b)
      peak = std::max(peak, Eigen::Vector3d(row[1 + 6 * b], row[2 + 6 * b], row[3 + 6 * b]).norm());
  Eigen::AlignedBox3d extent;
  for (const auto& b : h->model.bodies) extent.extend(b.com);
  const double scale = peak > 0 ? 0.1 * std::max(extent.diagonal().norm(), 0.5) / peak : 1.0;
  return [&run, h, bodies, scale](double t) {
    return drawHamsasMoved(*run.isolator, *h, isolatorMotionAt(run, bodies, t), scale, strf("t = %.3f s (motion x %.3g)", t, scale));
  };
}

/// A run's geometry at a time for its .pvd: the points (xyz, m) and the frame's file
/// from them, its displacement from the first frame and its time.
struct PvdFrames {
  std::function<std::vector<double>(double t)> points;
  std::function<std::string(const std::vector<double>& xyz, const std::vector<double>& moved, double t)> file;
};

PvdFrames articlePvd(const RunDir& run) {
  std::shared_ptr<Model> model = buildArticleModel(run.scene, ModelUse::TimeRun);
  checkRunModel(run, *model);
  auto state = std::make_shared<SimTK::State>(model->getReferenceState());
  auto names = std::make_shared<std::vector<std::string>>();
  for (const NamedPoint& p : model->getPoints()) names->push_back(p.name);
  PvdFrames f;
  f.points = [&run, model, state](double t) {
    setRunPose(rowAt(run.states, t), t, *model, *state);
    model->getSystem().realize(*state, SimTK::Stage::Position);
    std::vector<double> xyz;
    for (const NamedPoint& p : model->getPoints()) {
      const SimTK::Vec3 x = model->getMatter().getMobilizedBody(p.mobod).findStationLocationInGround(*state, p.station_B);
      xyz.insert(xyz.end(), {x[0], x[1], x[2]});
    }
    return xyz;
  };
  f.file = [&run, names](const std::vector<double>& xyz, const std::vector<double>& moved, double t) {
    return articlePoseVtp(*names, xyz, moved, run.scene.article, t);
  };
  return f;
}

/// HAM-SAS: each moving body's box (as modes.vtp has them) moved by its recorded motion,
/// true to scale (the videos magnify it; a .pvd leaves that to Warp By Vector).
PvdFrames isolatorPvd(const RunDir& run) {
  const std::shared_ptr<HamsasModes> h = isolatorOfRun(run);
  PvdFrames f;
  f.points = [&run, h](double t) { return hamsasCorners(h->model, isolatorMotionAt(run, h->model.bodies.size(), t)); };
  f.file = [h](const std::vector<double>& xyz, const std::vector<double>& moved, double t) {
    return hamsasPoseVtp(h->model, xyz, moved, t);
  };
  return f;
}

/// FILE.pvd: the run's frames (those a video at --fps and --speed would show) as VTK
/// files in FILE_frames/ beside it, each the article's points (or the isolator's boxes)
/// at its time, and the collection that lists them with their times. The frames are one
/// transaction (OutputDir); the collection is written last, and a failure there puts the
/// frames back.
void writeRunPvd(const RenderArgs& args, const RunDir& run) {
  for (const char* o : {"--traces", "--at", "--size", "--view"})
    if (args.given.count(o)) throw UsageError(std::string("render --history --out FILE.pvd: ") + o + " draws pictures; a .pvd holds the geometry (drop it)");
  const fs::path pvd(args.out);
  std::error_code ec;
  if (fs::exists(pvd, ec) && !args.force) throw OutputError(args.out + ": exists (use --force to replace it)");
  const PvdFrames geometry = run.isolator ? isolatorPvd(run) : articlePvd(run);
  const double t0 = run.states.rows.front()[0], t1 = run.states.rows.back()[0];
  const double frames = std::floor((t1 - t0) / args.speed * args.fps) + 1;
  if (frames > kMaxFrames)
    throw UsageError(strf("render --history: %.0f frames at %g frames/s and speed %g (limit %d): lower --fps or raise --speed",
                          frames, args.fps, args.speed, kMaxFrames));
  const std::string folder = pvd.stem().string() + "_frames";
  OutputDir out((pvd.has_parent_path() ? pvd.parent_path() / folder : fs::path(folder)).string(), args.force);
  out.reportAsOne("frames (.vtp)");
  std::vector<double> first;
  std::vector<std::pair<double, std::string>> listed;
  const ProgressStage stage("writing the run's frames");
  for (int k = 0; k < static_cast<int>(frames); ++k) {
    progressCount(k + 1, static_cast<long>(frames), "frame");
    const double t = t0 + k * args.speed / args.fps;
    const std::vector<double> xyz = geometry.points(t);
    if (first.empty()) first = xyz;
    std::vector<double> moved(xyz.size());
    for (std::size_t i = 0; i < xyz.size(); ++i) moved[i] = xyz[i] - first[i];
    const std::string name = strf("frame_%05d.vtp", k);
    out.write(name, geometry.file(xyz, moved, t));
    listed.emplace_back(t, folder + "/" + name);
  }
  out.commit();
  writeAtomically(args.out, args.force, [&](const std::string& p) { writeFileChecked(p, pvdCollection(listed)); });
}

}  // namespace

void renderHistory(const RenderArgs& args, const std::string& ext) {
  if (args.segments || args.no_gravity || !args.sets.empty())
    throw UsageError("render --history: the run's own segments, gravity and overrides are used (run.json); drop --segments, --no-gravity and --set");
  render::FrameOptions size, frame;
  parseSize(args.size, size, ext);
  frame = size;  // with traces, the drawing takes the left 60 % and the traces the rest
  if (!args.traces.empty()) frame.width = std::max(16, size.width * 3 / 5);
  const RunDir run = readRunDir(args.history, args.scene_path);
  if (ext == ".pvd") return writeRunPvd(args, run);
  std::shared_ptr<Model> model;
  std::shared_ptr<HamsasModes> isolator;
  const DrawAt drawAt = run.isolator ? isolatorFrames(run, isolator) : articleFrames(run, model);
  const std::vector<render::Trace> traces = tracesFor(run, args.traces);
  const double t0 = run.states.rows.front()[0], t1 = run.states.rows.back()[0];
  // One camera for the whole run: the presets frame where the article goes over it.
  Eigen::AlignedBox3d reach;
  for (int k = 0; k <= 24; ++k) reach.extend(drawAt(t0 + (t1 - t0) * k / 24).bounds());
  // A spatial run leaves the plane the front view looks along: iso unless a view is given.
  const bool spatial = !run.isolator && run.scene.article.model == ArticleModel::Spatial;
  const std::string view = !args.view.empty() ? args.view : spatial ? "iso" : "front";
  const Camera camera = chooseCamera(view, drawAt(t0), run.isolator ? std::vector<CameraView>{} : run.scene.views, reach);
  auto image = [&](double t) {
    const cv::Mat article = render::renderFrame(drawAt(t), camera, frame);
    if (traces.empty()) return article;
    cv::Mat img;
    cv::hconcat(article, render::tracePanel(traces, t, cv::Size(size.width - frame.width, size.height)), img);
    render::layoutArrangeRow(2);  // the figure harness sees one image
    return img;
  };
  if (ext == ".png") {
    const double t = args.at < 0 ? t1 : args.at;
    if (t < t0 || t > t1) throw UsageError(strf("--at %g: the run spans %g to %g s", t, t0, t1));
    const cv::Mat img = image(t);
    writeAtomically(args.out, args.force, [&](const std::string& p) { render::writePng(p, img); });
    return;
  }
  if (args.at >= 0) throw UsageError("--at draws one frame: write a .png");
  frame.supersample = kVideoSupersample;
  const double frames = std::floor((t1 - t0) / args.speed * args.fps) + 1;
  if (frames > kMaxFrames)
    throw UsageError(strf("render --history: %.0f frames at %g frames/s and speed %g (limit %d): lower --fps or raise --speed",
                          frames, args.fps, args.speed, kMaxFrames));
  writeAtomically(args.out, args.force, [&](const std::string& p) {
    render::VideoSink video(p, args.fps, cv::Size(size.width, size.height));
    const ProgressStage stage("drawing the run's frames");
    for (int k = 0; k < static_cast<int>(frames); ++k) {
      progressCount(k + 1, static_cast<long>(frames), "frame");
      video.write(image(t0 + k * args.speed / args.fps));
    }
    video.close();
  });
}

}  // namespace mmv::cli

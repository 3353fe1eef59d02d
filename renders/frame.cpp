#include "renders/frame.hpp"

#include <GL/osmesa.h>
#include <GL/gl.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

namespace mmv::render {
namespace {

constexpr double kNear = 0.01;  ///< m, the near clip distance.

/// The OSMesa context and its colour buffer (RAII).
class Context {
 public:
  Context(int w, int h) : buffer_(static_cast<std::size_t>(w) * h * 4) {
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!ctx_) throw std::runtime_error("OSMesa: cannot create a context");
    if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w, h)) {
      OSMesaDestroyContext(ctx_);
      throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(w) + " x " + std::to_string(h) + " buffer");
    }
  }
  ~Context() { OSMesaDestroyContext(ctx_); }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  const std::vector<unsigned char>& buffer() const { return buffer_; }

 private:
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
};

/// World to camera (OpenGL's view matrix).
Eigen::Matrix4d viewMatrix(const Camera& c) {
  const Eigen::Vector3d f = (c.target - c.eye).normalized();
  const Eigen::Vector3d s = f.cross(c.up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = s.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -s.dot(c.eye);
  m(1, 3) = -u.dot(c.eye);
  m(2, 3) = f.dot(c.eye);
  return m;
}

/// Perspective projection; the far plane is far enough for anything the camera frames.
Eigen::Matrix4d projectionMatrix(const Camera& c, double aspect) {
  const double far = std::max(100.0, 4 * (c.eye - c.target).norm());
  const double t = 1.0 / std::tan(0.5 * c.fov_deg * M_PI / 180);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = t / aspect;
  p(1, 1) = t;
  p(2, 2) = -(far + kNear) / (far - kNear);
  p(2, 3) = -2 * far * kNear / (far - kNear);
  p(3, 2) = -1;
  return p;
}

void vertex(const Eigen::Isometry3d& T, const Eigen::Vector3d& p) {
  const Eigen::Vector3d w = T * p;
  glVertex3d(w.x(), w.y(), w.z());
}

void normal(const Eigen::Isometry3d& T, const Eigen::Vector3d& n) {
  const Eigen::Vector3d w = T.linear() * n;
  glNormal3d(w.x(), w.y(), w.z());
}

void drawBox(const DrawItem& it) {
  const Eigen::Vector3d h = 0.5 * it.size;
  static const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  static const double normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  glBegin(GL_QUADS);
  for (int f = 0; f < 6; ++f) {
    normal(it.pose, Eigen::Vector3d(normals[f][0], normals[f][1], normals[f][2]));
    for (int v : faces[f])
      vertex(it.pose, Eigen::Vector3d((v & 1) ? h.x() : -h.x(), (v & 2) ? h.y() : -h.y(), (v & 4) ? h.z() : -h.z()));
  }
  glEnd();
}

void drawCylinder(const DrawItem& it) {
  constexpr int n = 32;
  const double l = 0.5 * it.size.x(), r = 0.5 * it.size.y();
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * M_PI * i / n, cy = std::cos(a), sz = std::sin(a);
    normal(it.pose, Eigen::Vector3d(0, cy, sz));
    vertex(it.pose, Eigen::Vector3d(-l, r * cy, r * sz));
    vertex(it.pose, Eigen::Vector3d(l, r * cy, r * sz));
  }
  glEnd();
  for (int side : {-1, 1}) {
    glBegin(GL_TRIANGLE_FAN);
    normal(it.pose, Eigen::Vector3d(side, 0, 0));
    vertex(it.pose, Eigen::Vector3d(side * l, 0, 0));
    for (int i = 0; i <= n; ++i) {
      const double a = 2 * M_PI * i / n * side;
      vertex(it.pose, Eigen::Vector3d(side * l, r * std::cos(a), r * std::sin(a)));
    }
    glEnd();
  }
}

void drawSphere(const DrawItem& it) {
  constexpr int rings = 16, segments = 24;
  const double r = 0.5 * it.size.x();
  for (int i = 0; i < rings; ++i) {
    const double a0 = M_PI * i / rings - M_PI / 2, a1 = M_PI * (i + 1) / rings - M_PI / 2;
    glBegin(GL_QUAD_STRIP);
    for (int j = 0; j <= segments; ++j) {
      const double b = 2 * M_PI * j / segments;
      for (double a : {a1, a0}) {
        const Eigen::Vector3d n(std::cos(a) * std::cos(b), std::sin(a), std::cos(a) * std::sin(b));
        normal(it.pose, n);
        vertex(it.pose, r * n);
      }
    }
    glEnd();
  }
}

/// The colour of a value on the colour bar: OpenCV's viridis colormap.
std::array<float, 4> barColor(const ColorBar& bar, double value, float alpha) {
  const double t = bar.max > bar.min ? std::clamp((value - bar.min) / (bar.max - bar.min), 0.0, 1.0) : 0.0;
  cv::Mat v(1, 1, CV_8UC1, cv::Scalar(std::lround(255 * t))), c;
  cv::applyColorMap(v, c, cv::COLORMAP_VIRIDIS);
  const cv::Vec3b b = c.at<cv::Vec3b>(0);
  return {b[2] / 255.0f, b[1] / 255.0f, b[0] / 255.0f, alpha};
}

void drawItem(const DrawItem& it, const DrawList& list) {
  const std::array<float, 4> rgba = std::isfinite(it.value) ? barColor(list.color_bar, it.value, it.rgba[3]) : it.rgba;
  glColor4f(rgba[0], rgba[1], rgba[2], rgba[3]);
  switch (it.shape) {
    case DrawItem::Shape::Box: drawBox(it); break;
    case DrawItem::Shape::Cylinder: drawCylinder(it); break;
    case DrawItem::Shape::Sphere: drawSphere(it); break;
  }
}

void setUpScene(const Camera& camera, int w, int h) {
  glViewport(0, 0, w, h);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_NORMALIZE);
  glShadeModel(GL_SMOOTH);
  glMatrixMode(GL_PROJECTION);
  const Eigen::Matrix4d P = projectionMatrix(camera, static_cast<double>(w) / h);
  glLoadMatrixd(P.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  // Lights fixed to the camera: a key light from the upper left and a weaker fill.
  glEnable(GL_LIGHTING);
  glEnable(GL_COLOR_MATERIAL);
  glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);  // normals as given, whatever the winding
  const GLfloat ambient[] = {0.25f, 0.25f, 0.25f, 1}, key[] = {0.75f, 0.75f, 0.75f, 1}, fill[] = {0.3f, 0.3f, 0.3f, 1};
  const GLfloat key_dir[] = {-0.4f, 0.6f, 1.0f, 0}, fill_dir[] = {0.6f, -0.3f, 0.5f, 0};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, key);
  glLightfv(GL_LIGHT0, GL_POSITION, key_dir);
  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill);
  glLightfv(GL_LIGHT1, GL_POSITION, fill_dir);
  const Eigen::Matrix4d V = viewMatrix(camera);
  glLoadMatrixd(V.data());
}

cv::Scalar bgr(const std::array<float, 4>& c) { return cv::Scalar(255 * c[2], 255 * c[1], 255 * c[0]); }

/// A bar of a round length (1, 2 or 5 x 10^k m) about a fifth of the frame wide, at the
/// target's distance.
void drawScaleBar(cv::Mat& img, const Camera& c) {
  const double dist = (c.target - c.eye).norm();
  const double metres_per_px = 2 * dist * std::tan(0.5 * c.fov_deg * M_PI / 180) / img.rows;
  const double want = 0.2 * img.cols * metres_per_px;
  const double base = std::pow(10.0, std::floor(std::log10(want)));
  double len = base;
  for (double f : {2.0, 5.0})
    if (f * base <= want) len = f * base;
  const int px = static_cast<int>(std::lround(len / metres_per_px));
  const cv::Point a(20, img.rows - 24), b(20 + px, img.rows - 24);
  cv::line(img, a, b, cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  cv::line(img, a + cv::Point(0, -6), a + cv::Point(0, 6), cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  cv::line(img, b + cv::Point(0, -6), b + cv::Point(0, 6), cv::Scalar(0, 0, 0), 2, cv::LINE_AA);
  char text[32];
  std::snprintf(text, sizeof text, "%g m (at the target)", len);
  cv::putText(img, text, cv::Point(20, img.rows - 34), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

void drawColorBar(cv::Mat& img, const ColorBar& bar) {
  const int x0 = img.cols - 70, y0 = 60, height = std::max(80, img.rows / 2), width = 18;
  cv::Mat ramp(height, 1, CV_8UC1);
  for (int i = 0; i < height; ++i) ramp.at<unsigned char>(i) = static_cast<unsigned char>(255 - 255 * i / (height - 1));
  cv::Mat colored;
  cv::applyColorMap(ramp, colored, cv::COLORMAP_VIRIDIS);
  for (int i = 0; i < height; ++i) cv::line(img, {x0, y0 + i}, {x0 + width, y0 + i}, colored.at<cv::Vec3b>(i), 1);
  cv::rectangle(img, {x0, y0}, {x0 + width, y0 + height - 1}, cv::Scalar(0, 0, 0), 1);
  char top[32], bottom[32];
  std::snprintf(top, sizeof top, "%.3g", bar.max);
  std::snprintf(bottom, sizeof bottom, "%.3g", bar.min);
  cv::putText(img, top, {x0 - 6, y0 - 6}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  cv::putText(img, bottom, {x0 - 6, y0 + height + 16}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  int base = 0;
  const cv::Size t = cv::getTextSize(bar.title, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &base);
  cv::putText(img, bar.title, {std::max(4, img.cols - t.width - 8), y0 + height + 36}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

void annotate(cv::Mat& img, const DrawList& list, const Camera& camera) {
  cv::putText(img, list.title, {14, 26}, cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  for (const auto& l : list.labels) {
    cv::Point2d p;
    if (!projectPoint(camera, img.cols, img.rows, l.at, p)) continue;
    cv::circle(img, p, 3, bgr(l.rgba), -1, cv::LINE_AA);
    cv::putText(img, l.text, p + cv::Point2d(6, -6), cv::FONT_HERSHEY_SIMPLEX, 0.42, bgr(l.rgba), 1, cv::LINE_AA);
  }
  int y = 50;
  for (const auto& [name, color] : list.legend) {
    cv::rectangle(img, {14, y - 10}, {26, y + 2}, bgr(color), -1);
    cv::putText(img, name, {32, y}, cv::FONT_HERSHEY_SIMPLEX, 0.45, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    y += 18;
  }
  drawScaleBar(img, camera);
  if (list.has_color_bar) drawColorBar(img, list.color_bar);
}

}  // namespace

bool projectPoint(const Camera& camera, int width, int height, const Eigen::Vector3d& p, cv::Point2d& pixel) {
  const Eigen::Vector4d clip =
      projectionMatrix(camera, static_cast<double>(width) / height) * viewMatrix(camera) * p.homogeneous();
  if (clip.w() <= kNear) return false;
  pixel.x = (clip.x() / clip.w() + 1) * 0.5 * width;
  pixel.y = (1 - clip.y() / clip.w()) * 0.5 * height;
  return true;
}

cv::Mat renderFrame(const DrawList& list, const Camera& camera, const FrameOptions& o) {
  const int k = std::max(1, o.supersample), w = o.width * k, h = o.height * k;
  // One context per thread, made anew only when the size changes (an animation's
  // frames share it; creating one costs more than drawing a frame).
  thread_local std::unique_ptr<Context> cached;
  thread_local int cached_w = 0, cached_h = 0;
  if (!cached || cached_w != w || cached_h != h) {
    cached.reset();
    cached = std::make_unique<Context>(w, h);
    cached_w = w;
    cached_h = h;
  }
  const Context& ctx = *cached;
  setUpScene(camera, w, h);
  for (const auto& it : list.items)
    if (it.rgba[3] >= 1) drawItem(it, list);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  for (const auto& it : list.items)
    if (it.rgba[3] < 1) drawItem(it, list);
  glDepthMask(GL_TRUE);
  glFinish();
  const cv::Mat rgba(h, w, CV_8UC4, const_cast<unsigned char*>(ctx.buffer().data()));
  cv::Mat bgr_big, flipped, out;
  cv::cvtColor(rgba, bgr_big, cv::COLOR_RGBA2BGR);
  cv::flip(bgr_big, flipped, 0);  // OpenGL's rows run bottom-up
  cv::resize(flipped, out, cv::Size(o.width, o.height), 0, 0, cv::INTER_AREA);
  annotate(out, list, camera);
  return out;
}

cv::Mat contactSheet(const std::vector<cv::Mat>& tiles, int columns) {
  if (tiles.empty()) return {};
  const int rows = (static_cast<int>(tiles.size()) + columns - 1) / columns;
  cv::Mat sheet(rows * tiles[0].rows, columns * tiles[0].cols, CV_8UC3, cv::Scalar(255, 255, 255));
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int r = static_cast<int>(i) / columns, c = static_cast<int>(i) % columns;
    tiles[i].copyTo(sheet(cv::Rect(c * tiles[0].cols, r * tiles[0].rows, tiles[0].cols, tiles[0].rows)));
  }
  return sheet;
}

void writePng(const std::string& path, const cv::Mat& image) {
  if (!cv::imwrite(path, image)) throw std::runtime_error(path + ": cannot write the PNG");
}

void writeVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps) {
  if (frames.empty()) throw std::runtime_error(path + ": no frames");
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  int fourcc = 0;
  if (ext == ".mp4") fourcc = cv::VideoWriter::fourcc('m', 'p', '4', 'v');
  else if (ext == ".avi") fourcc = cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
  else throw std::runtime_error(path + ": a video is .mp4 or .avi");
  cv::VideoWriter writer(path, cv::CAP_FFMPEG, fourcc, fps, frames[0].size());
  if (!writer.isOpened()) throw std::runtime_error(path + ": cannot open the video encoder");
  for (const auto& f : frames) writer.write(f);
}

}  // namespace mmv::render

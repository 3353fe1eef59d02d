#include "renders/frame.hpp"
#include "renders/layout.hpp"
#include "renders/png.hpp"
#include "renders/video_api.hpp"
#include "renders/label_space.hpp"

#include <GL/osmesa.h>
#include <sys/mman.h>
#include <GL/gl.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "sim/core/errors.hpp"
#include "sim/core/files.hpp"
#include "sim/core/plugins.hpp"

namespace mmv::render {
namespace {

constexpr double kNear = 0.01;  ///< m, the near clip distance.

/// The OSMesa context and its colour buffer (RAII): an anonymous mapping on transparent
/// huge pages where the kernel gives them (madvise mode), zero pages until the clear
/// writes them (a zero-filled vector wrote all of it once more, on 4 kB pages).
class Context {
 public:
  Context(int w, int h) : bytes_(static_cast<std::size_t>(w) * h * 4) {
    void* p = mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::runtime_error("cannot map a " + std::to_string(w) + " x " + std::to_string(h) + " frame buffer");
    buffer_ = static_cast<unsigned char*>(p);
    madvise(buffer_, bytes_, MADV_HUGEPAGE);
    ctx_ = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!ctx_) {
      munmap(buffer_, bytes_);
      throw std::runtime_error("OSMesa: cannot create a context");
    }
    if (!OSMesaMakeCurrent(ctx_, buffer_, GL_UNSIGNED_BYTE, w, h)) {
      OSMesaDestroyContext(ctx_);
      munmap(buffer_, bytes_);
      throw std::runtime_error("OSMesa: cannot bind a " + std::to_string(w) + " x " + std::to_string(h) + " buffer");
    }
  }
  ~Context() {
    OSMesaDestroyContext(ctx_);
    munmap(buffer_, bytes_);
  }
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  const unsigned char* buffer() const { return buffer_; }

 private:
  OSMesaContext ctx_ = nullptr;
  std::size_t bytes_ = 0;
  unsigned char* buffer_ = nullptr;
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

/// Triangles in the item's own frame (a unit shape scaled by its size): positions and
/// normals, three vertices a triangle.
struct Mesh {
  std::vector<Eigen::Vector3f> p, n;
  void quad(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& d,
            const Eigen::Vector3d& na, const Eigen::Vector3d& nb, const Eigen::Vector3d& nc, const Eigen::Vector3d& nd) {
    for (const Eigen::Vector3d* v : {&a, &b, &c, &a, &c, &d}) p.push_back(v->cast<float>());
    for (const Eigen::Vector3d* v : {&na, &nb, &nc, &na, &nc, &nd}) n.push_back(v->cast<float>());
  }
  void triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, const Eigen::Vector3d& nn) {
    for (const Eigen::Vector3d* v : {&a, &b, &c}) p.push_back(v->cast<float>());
    for (int i = 0; i < 3; ++i) n.push_back(nn.cast<float>());
  }
};

/// A box of half-sizes 1/2 (the unit cube), flat faces.
Mesh unitBox() {
  Mesh m;
  static const int faces[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  static const double normals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  auto corner = [](int v) { return Eigen::Vector3d((v & 1) ? 0.5 : -0.5, (v & 2) ? 0.5 : -0.5, (v & 4) ? 0.5 : -0.5); };
  for (int f = 0; f < 6; ++f) {
    const Eigen::Vector3d nn(normals[f][0], normals[f][1], normals[f][2]);
    m.quad(corner(faces[f][0]), corner(faces[f][1]), corner(faces[f][2]), corner(faces[f][3]), nn, nn, nn, nn);
  }
  return m;
}

/// A cylinder of length 1 along x and diameter 1, smooth sides and flat ends.
Mesh unitCylinder() {
  constexpr int n = 32;
  Mesh m;
  auto ring = [](int i) { const double a = 2 * M_PI * i / n; return Eigen::Vector3d(0, 0.5 * std::cos(a), 0.5 * std::sin(a)); };
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r0 = ring(i), r1 = ring(i + 1), l(0.5, 0, 0);
    m.quad(r0 - l, r1 - l, r1 + l, r0 + l, 2 * r0, 2 * r1, 2 * r1, 2 * r0);
    for (int side : {-1, 1}) {
      const Eigen::Vector3d c = side * l, nn(side, 0, 0);
      m.triangle(c, c + (side > 0 ? r0 : r1), c + (side > 0 ? r1 : r0), nn);
    }
  }
  return m;
}

/// A sphere of diameter 1, 16 rings of 24 segments.
Mesh unitSphere() {
  constexpr int rings = 16, segments = 24;
  Mesh m;
  auto at = [](int i, int j) {
    const double a = M_PI * i / rings - M_PI / 2, b = 2 * M_PI * j / segments;
    return Eigen::Vector3d(std::cos(a) * std::cos(b), std::sin(a), std::cos(a) * std::sin(b));
  };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const Eigen::Vector3d a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      m.quad(0.5 * a, 0.5 * b, 0.5 * c, 0.5 * d, a, b, c, d);
    }
  return m;
}

const Mesh& unitMesh(DrawItem::Shape shape) {
  static const Mesh box = unitBox(), cylinder = unitCylinder(), sphere = unitSphere();
  switch (shape) {
    case DrawItem::Shape::Cylinder: return cylinder;
    case DrawItem::Shape::Sphere: return sphere;
    case DrawItem::Shape::Box: break;
  }
  return box;
}

/// OpenCV's viridis colormap as 256 RGB triples (looked up once).
const std::array<std::array<float, 3>, 256>& viridis() {
  static const std::array<std::array<float, 3>, 256> table = [] {
    cv::Mat ramp(1, 256, CV_8UC1), colored;
    for (int i = 0; i < 256; ++i) ramp.at<unsigned char>(i) = static_cast<unsigned char>(i);
    cv::applyColorMap(ramp, colored, cv::COLORMAP_VIRIDIS);
    std::array<std::array<float, 3>, 256> t{};
    for (int i = 0; i < 256; ++i) {
      const cv::Vec3b b = colored.at<cv::Vec3b>(i);
      t[i] = {b[2] / 255.0f, b[1] / 255.0f, b[0] / 255.0f};
    }
    return t;
  }();
  return table;
}

/// The colour of a value on the colour bar.
std::array<float, 4> barColor(const ColorBar& bar, double value, float alpha) {
  double t = bar.max > bar.min ? std::clamp((value - bar.min) / (bar.max - bar.min), 0.0, 1.0) : 0.0;
  if (!std::isfinite(t)) t = 0;  // an infinite bar: the table index must stay in range
  const auto& c = viridis()[static_cast<std::size_t>(std::lround(255 * t))];
  return {c[0], c[1], c[2], alpha};
}

/// Interleaved vertex data for glInterleavedArrays(GL_C4F_N3F_V3F): colour, normal, position.
using VertexBuffer = std::vector<float>;

/// Writes `it`'s vertices at `out` (vertexFloats(it) of them) and returns the end.
float* writeItem(float* out, const DrawItem& it, const DrawList& list) {
  const std::array<float, 4> rgba = std::isfinite(it.value) ? barColor(list.color_bar, it.value, it.rgba[3]) : it.rgba;
  const Mesh& m = unitMesh(it.shape);
  Eigen::Vector3d scale = it.size;
  if (it.shape == DrawItem::Shape::Sphere) scale.setConstant(it.size.x());
  if (it.shape == DrawItem::Shape::Cylinder) scale.z() = scale.y();
  // Positions map by R S, normals by R S^-1 (normalised by GL_NORMALIZE), in floats:
  // the frame's precision is a pixel, far coarser than a float's.
  const Eigen::Matrix3d R = it.pose.linear();
  const Eigen::Matrix3f A = (R * scale.asDiagonal()).cast<float>();
  const Eigen::Matrix3f N = (R * scale.cwiseMax(1e-12).cwiseInverse().asDiagonal()).cast<float>();
  const Eigen::Vector3f t = it.pose.translation().cast<float>();
  for (std::size_t i = 0; i < m.p.size(); ++i, out += 10) {
    const Eigen::Vector3f &p = m.p[i], &n = m.n[i];
    out[0] = rgba[0], out[1] = rgba[1], out[2] = rgba[2], out[3] = rgba[3];
    for (int r = 0; r < 3; ++r) {  // written out: Eigen's 3 x 3 product is a call a vertex at -O1
      out[4 + r] = N(r, 0) * n.x() + N(r, 1) * n.y() + N(r, 2) * n.z();
      out[7 + r] = A(r, 0) * p.x() + A(r, 1) * p.y() + A(r, 2) * p.z() + t[r];
    }
  }
  return out;
}

std::size_t vertexFloats(const DrawItem& it) { return 10 * unitMesh(it.shape).p.size(); }  ///< writeItem's

void drawBuffer(const VertexBuffer& vb) {
  if (vb.empty()) return;
  glInterleavedArrays(GL_C4F_N3F_V3F, 0, vb.data());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(vb.size() / 10));
}

void setUpScene(const Camera& camera, int w, int h) {
  glViewport(0, 0, w, h);
  glClearColor(1, 1, 1, 1);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
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
/// target's distance. Returns the box it takes (bar and text).
cv::Rect drawScaleBar(cv::Mat& img, const Camera& c) {
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
  putTextLogged(img, text, cv::Point(20, img.rows - 34), 0.5, cv::Scalar(0, 0, 0));
  return textBox(text, cv::Point(20, img.rows - 34), 0.5) | cv::Rect(a.x - 2, a.y - 7, px + 4, 14);
}

/// The colour bar at the frame's right edge, its range and title. Returns the box it takes.
cv::Rect drawColorBar(cv::Mat& img, const ColorBar& bar) {
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
  putTextLogged(img, top, {x0 - 6, y0 - 6}, 0.45, cv::Scalar(0, 0, 0));
  putTextLogged(img, bottom, {x0 - 6, y0 + height + 16}, 0.45, cv::Scalar(0, 0, 0));
  int base = 0;
  const cv::Size t = cv::getTextSize(bar.title, cv::FONT_HERSHEY_SIMPLEX, 0.45, 1, &base);
  const cv::Point title_at(std::max(4, img.cols - t.width - 8), y0 + height + 36);
  putTextLogged(img, bar.title, title_at, 0.45, cv::Scalar(0, 0, 0));
  return textBox(top, {x0 - 6, y0 - 6}, 0.45) | textBox(bar.title, title_at, 0.45) | cv::Rect(x0 - 6, y0, img.cols - x0 + 6, height);
}

void annotate(cv::Mat& img, const DrawList& list, const Camera& camera, const cv::Mat& ink) {
  double title_scale = 0.6;  // a long title (a small frame, a contact sheet's tile) is set smaller, never cut
  for (int base = 0; title_scale > 0.3 && cv::getTextSize(list.title, cv::FONT_HERSHEY_SIMPLEX, title_scale, 1, &base).width > img.cols - 28;)
    title_scale *= 0.93;
  putTextLogged(img, list.title, {14, 26}, title_scale, cv::Scalar(0, 0, 0));
  // The legend, the scale bar and the colour bar first: labels keep clear of them (and of
  // the title).
  LabelSpace space(img.size(), ink);
  std::vector<cv::Rect>& taken = space.taken;
  taken.emplace_back(0, 0, img.cols, kTitleBand);
  taken.push_back(drawScaleBar(img, camera));
  if (list.has_color_bar) taken.push_back(drawColorBar(img, list.color_bar));
  int y = kLegendFirstRow;
  for (const auto& [name, color] : list.legend) {
    cv::rectangle(img, {14, y - 10}, {26, y + 2}, bgr(color), -1);
    putTextLogged(img, name, {32, y}, 0.45, cv::Scalar(0, 0, 0));
    y += kLegendRow;
  }
  if (!list.legend.empty()) taken.push_back(legendArea(list));
  for (const auto& l : list.labels) {
    cv::Point2d p;
    // A point out of the picture (the lab's ceiling above a close view): its label too.
    if (l.room && !camera.room) continue;
    if (!projectPoint(camera, img.cols, img.rows, l.at, p) || p.x < 0 || p.y < 0 || p.x >= img.cols || p.y >= img.rows) continue;
    cv::circle(img, p, 3, bgr(l.rgba), -1, cv::LINE_AA);
    const cv::Point text = placeLabel(l.text, p, space);
    if (std::abs(text.y - 4 - p.y) > 8 || text.x < p.x)  // moved away: a leader line to its point
      cv::line(img, p, cv::Point(text.x < p.x ? text.x + taken.back().width : text.x, text.y - 4), bgr(l.rgba), 1, cv::LINE_AA);
    putTextLogged(img, l.text, text, 0.42, bgr(l.rgba));
  }
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

int effectiveSupersample(const FrameOptions& o) {
  return std::max(1, std::min(o.supersample, kMaxBufferSide / std::max({o.width, o.height, 1})));
}

cv::Mat renderFrame(const DrawList& list, const Camera& preset, const FrameOptions& o) {
  const Camera camera = framedCamera(preset, list, o.width, o.height);
  const int k = effectiveSupersample(o), w = o.width * k, h = o.height * k;
  // One context per thread, made anew only when the size changes (an animation's
  // frames share it; creating one costs more than drawing a frame).
  thread_local std::unique_ptr<Context> cached;
  thread_local int cached_w = 0, cached_h = 0;
  if (!cached || cached_w != w || cached_h != h) {
    cached.reset();
    checkFrameMemory(w, h, o.width, o.height);
    cached = std::make_unique<Context>(w, h);
    cached_w = w;
    cached_h = h;
  }
  const Context& ctx = *cached;
  setUpScene(camera, w, h);
  // Opaque surroundings, then the opaque rest marking its pixels in the stencil, then
  // the translucent rest, then translucent surroundings only where nothing is marked: a
  // translucent platform over the article would grey it (issue 36: slew.png).
  VertexBuffer opaque_context, opaque, translucent, translucent_context;
  const auto bufferOf = [&](const DrawItem& it) -> VertexBuffer& {  // solid or not, context or not
    return it.context ? (it.rgba[3] >= 1 ? opaque_context : translucent_context) : (it.rgba[3] >= 1 ? opaque : translucent);
  };
  std::map<VertexBuffer*, std::size_t> size;  // each buffer sized once, written in place
  for (const auto& it : list.items)
    if (!it.room || camera.room) size[&bufferOf(it)] += vertexFloats(it);
  std::map<VertexBuffer*, float*> end;
  for (const auto& [buffer, n] : size) buffer->resize(n), end[buffer] = buffer->data();
  for (const auto& it : list.items)
    if (!it.room || camera.room) end[&bufferOf(it)] = writeItem(end[&bufferOf(it)], it, list);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 1, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  drawBuffer(opaque_context);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  drawBuffer(opaque);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glDepthMask(GL_FALSE);
  drawBuffer(translucent);
  glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
  drawBuffer(translucent_context);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  glFinish();
  // What the opaque drawing marked (the article, not its surroundings), at the frame's
  // size: labels keep off it where they can.
  // A sample per pixel is enough to tell a label's place from the drawing (nearest, not
  // averaged: a video reads one per frame), into buffers kept for the next frame.
  cv::Mat ink;
  if (!list.labels.empty()) {
    thread_local cv::Mat stencil, small_stencil;
    stencil.create(h, w, CV_8UC1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data);
    cv::resize(stencil, small_stencil, cv::Size(o.width, o.height), 0, 0, cv::INTER_NEAREST);
    cv::flip(small_stencil, ink, 0);
  }
  // Reduce first (area averaging of the k x k samples), then flip and convert the
  // small image (OpenGL's rows run bottom-up), through buffers a video's next frame
  // reuses.
  const cv::Mat rgba(h, w, CV_8UC4, const_cast<unsigned char*>(ctx.buffer()));
  thread_local cv::Mat small, flipped;
  cv::Mat out;
  cv::resize(rgba, small, cv::Size(o.width, o.height), 0, 0, cv::INTER_AREA);
  cv::flip(small, flipped, 0);
  cv::cvtColor(flipped, out, cv::COLOR_RGBA2BGR);
  layoutNewImage(out.cols, out.rows, "frame");
  annotate(out, list, camera, ink);
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
  layoutArrangeSheet(tiles.size(), columns);
  return sheet;
}

void writePng(const std::string& path, const cv::Mat& image) {
  std::vector<unsigned char> png;
  try {
    png = encodePng(image);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": cannot encode the PNG: " + e.what());
  }
  writeFileChecked(path, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
  layoutFlush(path);
}

namespace {

/// The video plugin's table (renders/video_api.hpp), loaded on the first video.
const VideoApi& videoApi() {
  static const VideoApi* api = [] {
    std::string failure;
    const void* t = loadPluginTable(
        "libmmvlab_video.so", MMVLAB_VIDEO_PLUGIN, "mmvlab_video_api",
        [](const void* p) { return static_cast<const VideoApi*>(p)->version == kVideoApiVersion; }, "video plugin", failure);
    if (!t) throw UnavailableError("videos need libmmvlab_video.so (OpenCV's video I/O, FFmpeg): tried " + failure);
    return static_cast<const VideoApi*>(t);
  }();
  return *api;
}

}  // namespace

VideoSink::VideoSink(const std::string& path, double fps, cv::Size size) : path_(path), size_(size) {
  const auto dot = path.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  if (ext != ".mp4" && ext != ".avi") throw std::runtime_error(path + ": a video is .mp4 or .avi");
  api_ = &videoApi();
  writer_ = api_->open(path.c_str(), ext == ".mp4" ? VideoApi::kMp4 : VideoApi::kAvi, fps, size.width, size.height);
  if (!writer_) throw std::runtime_error(path + ": cannot open the video encoder");
}

VideoSink::~VideoSink() {
  if (writer_) api_->release(writer_);
}

void VideoSink::close() {
  if (!writer_) return;
  api_->release(writer_);
  writer_ = nullptr;
  // The encoder does not report a failed write: read the file back (a truncated MP4 has
  // no index and does not open, or opens short).
  syncFileChecked(path_);
  const long n = api_->frame_count(path_.c_str());
  if (n != frames_)
    throw std::runtime_error(path_ + ": the video did not write whole (" +
                             (n >= 0 ? std::to_string(n) + " of " + std::to_string(frames_) + " frames"
                                     : std::string("it does not open")) +
                             "; disk full?)");
}

void VideoSink::write(const cv::Mat& frame) {
  if (frame.size() != size_) throw std::runtime_error(path_ + ": a frame of another size");
  if (frame.type() != CV_8UC3) throw std::runtime_error(path_ + ": a frame is 8-bit BGR");
  api_->write(writer_, frame.data, frame.cols, frame.rows, frame.step[0]);
  ++frames_;
}

void writeVideo(const std::string& path, const std::vector<cv::Mat>& frames, double fps) {
  if (frames.empty()) throw std::runtime_error(path + ": no frames");
  VideoSink sink(path, fps, frames[0].size());
  for (const auto& f : frames) sink.write(f);
  sink.close();
}

}  // namespace mmv::render

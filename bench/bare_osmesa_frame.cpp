// The floor a frame of `mmvlab render` is measured against (issue 37: a 1280x720 frame at
// most 1.5x a bare OSMesa frame of the same size, whole process): one OSMesa context of
// that size, cleared, one lit triangle, read back, flipped and written as a PNG with
// mmvlab's own encoder (renders/png.hpp, libpng). No scene, no supersampling, no labels.
//   /usr/bin/time build/bench/bare_osmesa_frame 1280 720 /tmp/bare.png
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "renders/png.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s WIDTH HEIGHT OUT.png\n", argv[0]);
    return 64;
  }
  const int w = std::atoi(argv[1]), h = std::atoi(argv[2]);
  if (w <= 0 || h <= 0) return 64;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
  std::unique_ptr<unsigned char[]> buffer(new unsigned char[static_cast<std::size_t>(w) * h * 4]);
  if (!ctx || !OSMesaMakeCurrent(ctx, buffer.get(), GL_UNSIGNED_BYTE, w, h)) return 70;
  glViewport(0, 0, w, h);
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glBegin(GL_TRIANGLES);
  glNormal3f(0, 0, 1);
  glVertex3f(-0.5f, -0.5f, 0);
  glVertex3f(0.5f, -0.5f, 0);
  glVertex3f(0, 0.5f, 0);
  glEnd();
  glFinish();
  cv::Mat rgba(h, w, CV_8UC4, buffer.get()), bgr;
  cv::cvtColor(rgba, bgr, cv::COLOR_RGBA2BGR);
  cv::flip(bgr, bgr, 0);
  const std::vector<unsigned char> png = mmv::render::encodePng(bgr);
  std::FILE* f = std::fopen(argv[3], "wb");
  const bool written = f && std::fwrite(png.data(), 1, png.size(), f) == png.size();
  const bool ok = (f ? std::fclose(f) == 0 : false) && written;
  OSMesaDestroyContext(ctx);
  return ok ? 0 : 74;
}

// mujoco_swing: a free run of a model written by mjcf_export under MuJoCo's fixed-step
// RK4, from qpos0 at rest (mmvlab's `start: rest`), printing a site's x and y at each
// sample time (docs/benchmarks.md, "Against MuJoCo"; bench/scripts/mujoco_swing.py).
//
//   build/bench/mujoco_swing article.xml site timestep duration sample_rate > tip.csv
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

// MuJoCo's warnings to stderr: its default handler also appends them to MUJOCO_LOG.TXT in
// the working directory (the source tree, under the test suite).
void warn(const char* message) { std::fprintf(stderr, "mujoco_swing: MuJoCo: %s\n", message); }

}  // namespace

int main(int argc, char** argv) {
  mju_user_warning = warn;
  if (argc < 6) {
    std::fprintf(stderr, "usage: mujoco_swing article.xml site timestep duration sample_rate\n");
    return 64;
  }
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) {
    std::fprintf(stderr, "mujoco_swing: %s\n", error);
    return 1;
  }
  const int site = mj_name2id(m, mjOBJ_SITE, argv[2]);
  const double h = std::atof(argv[3]), duration = std::atof(argv[4]), rate = std::atof(argv[5]);
  const long per_sample = std::lround(1.0 / (rate * h));
  if (site < 0 || h <= 0 || per_sample < 1 || std::abs(per_sample * h * rate - 1) > 1e-9) {
    std::fprintf(stderr, "mujoco_swing: no site %s, or a step that does not divide the sample interval\n", argv[2]);
    return 64;
  }
  m->opt.timestep = h;
  m->opt.integrator = mjINT_RK4;
  mjData* d = mj_makeData(m);  // qpos0, at rest
  mj_forward(m, d);
  const long samples = std::lround(duration * rate);
  std::printf("t,x,y\n%.17g,%.17g,%.17g\n", 0.0, d->site_xpos[3 * site], d->site_xpos[3 * site + 1]);
  for (long k = 1; k <= samples; ++k) {
    for (long i = 0; i < per_sample; ++i) mj_step(m, d);
    for (int w = 0; w < mjNWARNING; ++w)
      if (d->warning[w].number > 0) {  // a NaN or huge state: MuJoCo reset it; the run is void
        std::fprintf(stderr, "mujoco_swing: unstable at t = %g s with a step of %g s\n", k / rate, h);
        return 3;
      }
    mj_kinematics(m, d);  // the site where the state now is (mj_step leaves it at the step's start)
    std::printf("%.17g,%.17g,%.17g\n", k / rate, d->site_xpos[3 * site], d->site_xpos[3 * site + 1]);
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}

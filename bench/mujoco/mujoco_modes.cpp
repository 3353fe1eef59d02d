// mujoco_modes: what `mmvlab modes` does, done by MuJoCo on a model written by mjcf_export
// (docs/benchmarks.md, "Against MuJoCo"): load and compile the MJCF, find the static
// equilibrium under gravity (Newton on f(q) = qfrc_passive - qfrc_bias at rest, its
// Jacobian by central differences), linearize there (K = -df/dq, M from mj_fullM) and
// solve the symmetric generalized eigenproblem for the lowest modes. Prints them in Hz,
// one a line, after "equilibrium <Newton steps> <|f|>".
//
//   build/bench/mujoco_modes article.xml [modes]
#include <mujoco/mujoco.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

Eigen::VectorXd force(const mjModel* m, mjData* d, const Eigen::VectorXd& q) {
  for (int i = 0; i < m->nq; ++i) d->qpos[i] = q[i];
  mju_zero(d->qvel, m->nv);
  mj_forward(m, d);
  Eigen::VectorXd f(m->nv);
  for (int i = 0; i < m->nv; ++i) f[i] = d->qfrc_passive[i] - d->qfrc_bias[i];
  return f;
}

Eigen::MatrixXd jacobian(const mjModel* m, mjData* d, const Eigen::VectorXd& q) {
  Eigen::MatrixXd J(m->nv, m->nv);
  for (int j = 0; j < m->nv; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(q[j]));
    Eigen::VectorXd a = q, b = q;
    a[j] += h, b[j] -= h;
    J.col(j) = (force(m, d, a) - force(m, d, b)) / (2 * h);
  }
  return J;
}

}  // namespace

static void warn(const char* message) { std::fprintf(stderr, "mujoco_modes: MuJoCo: %s\n", message); }  // no MUJOCO_LOG.TXT

int main(int argc, char** argv) {
  mju_user_warning = warn;
  if (argc < 2) {
    std::fprintf(stderr, "usage: mujoco_modes article.xml [modes]\n");
    return 64;
  }
  const int want = argc > 2 ? std::atoi(argv[2]) : 12;
  char error[1000] = "";
  mjModel* m = mj_loadXML(argv[1], nullptr, error, sizeof error);
  if (!m) {
    std::fprintf(stderr, "mujoco_modes: %s\n", error);
    return 1;
  }
  if (m->nq != m->nv) {
    std::fprintf(stderr, "mujoco_modes: hinges only (nq %d, nv %d)\n", m->nq, m->nv);
    return 1;
  }
  mjData* d = mj_makeData(m);
  Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(m->qpos0, m->nq);
  int steps = 0;
  Eigen::VectorXd f = force(m, d, q);
  for (; steps < 50 && f.cwiseAbs().maxCoeff() > 1e-10; ++steps) {
    q -= jacobian(m, d, q).lu().solve(f);
    f = force(m, d, q);
  }
  if (f.cwiseAbs().maxCoeff() > 1e-10) {
    std::fprintf(stderr, "mujoco_modes: no equilibrium after %d Newton steps (residual %g)\n", steps, f.cwiseAbs().maxCoeff());
    return 2;
  }
  Eigen::MatrixXd K = -jacobian(m, d, q);
  K = 0.5 * (K + K.transpose()).eval();
  force(m, d, q);  // d at the equilibrium: its mass matrix
  Eigen::MatrixXd M(m->nv, m->nv);
  mj_fullM(m, M.data(), d->qM);  // row-major and symmetric: the same matrix
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M);
  if (es.info() != Eigen::Success) {
    std::fprintf(stderr, "mujoco_modes: the eigen solution failed\n");
    return 2;
  }
  std::printf("equilibrium %d %.3g\n", steps, f.cwiseAbs().maxCoeff());
  for (int k = 0; k < std::min<int>(want, m->nv); ++k)
    std::printf("%.12g\n", std::sqrt(std::max(es.eigenvalues()[k], 0.0)) / (2 * M_PI));
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}

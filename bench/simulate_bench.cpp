// Cost of a time run (`mmvlab simulate`) against segments per link and integrator: the
// default MMV article, joint 2 slewing 0 -> 45 deg (cycloidal) in 1.5 s of simulated
// time at accuracy 1e-6, recorded at 50 Hz. Wall time per run; the counters give the
// integrator's steps and right-hand-side evaluations (realizations).
// Figures are recorded in docs/benchmarks.md with the command that produced them.

#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include "sim/model/article_builder.hpp"
#include "sim/model/tree_dynamics.hpp"
#include "sim/modes/system_modes.hpp"
#include "sim/scene/scene.hpp"
#include "facility/table_programs.hpp"
#include "sim/time/simulation.hpp"

namespace {

const char* const kIntegrators[] = {"rk_merson", "cpodes", "cvode_bdf", "arkode_dirk"};

void BM_Slew(benchmark::State& st) {
  mmv::ArticleScene s = mmv::loadDefaultScene();
  mmv::overrideSegments(s, static_cast<int>(st.range(0)));
  mmv::SlewSpec slew;
  slew.to = 45 * M_PI / 180;
  s.article.joints[1].slew = slew;
  s.simulation.duration = 1.5;
  s.simulation.sample_rate_hz = 50;
  s.simulation.accuracy = 1e-6;
  s.simulation.integrator = kIntegrators[st.range(1)];
  st.SetLabel(s.simulation.integrator);
  mmv::SimulationResult r;
  for (auto _ : st) r = mmv::simulate(s);
  st.counters["steps"] = r.steps;
  st.counters["evals"] = r.realizations;
}
BENCHMARK(BM_Slew)
    ->ArgsProduct({{4, 8, 16}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(2);

}  // namespace

// The accuracy contract (`simulate --target-error`, sim/time/target.hpp) on the
// shipped slew scene's first 2 s at 1e-4 m on link 3a's tip: the pilot trade, the
// whole run and its verification, as the command runs them.
#include "sim/time/target.hpp"

namespace {

void BM_TargetErrorSlew(benchmark::State& st) {
  mmv::ArticleScene s = mmv::loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml");
  s.simulation.duration = 2.0;
  mmv::TargetOptions o;
  o.target_m = 1e-4;
  o.points = {"link3a.tip"};
  mmv::TargetOutcome t;
  for (auto _ : st) t = mmv::runToTarget(mmv::articleTradeProblem(s), o);
  st.counters["pilot_s"] = t.pilot.total_seconds;
  st.counters["run_s"] = t.attempts.back().run_seconds;
  st.counters["verification_s"] = t.attempts.back().companion_seconds;
  st.counters["attempts"] = static_cast<double>(t.attempts.size());
  st.SetLabel(t.attempts.back().integrator);
}
BENCHMARK(BM_TargetErrorSlew)->Unit(benchmark::kMillisecond)->Iterations(2);

// What one right-hand side costs on the slew scene's model (8 segments per link), and
// what a link carried by K modal coordinates (issue 12: q = T p, T constant) would need
// in its place: the reduced mass T^T M T (Simbody's M, n x n, then the product) and the
// generalized forces T^T (f - c) by one inverse-dynamics pass. Arg: 0 the full right-hand
// side (realize to Acceleration), 1 M alone, 2 the inverse-dynamics pass alone, 3 eight
// products M v (the reduced mass of 8 modal coordinates by columns, O(n) each).
void BM_RightHandSideParts(benchmark::State& st) {
  const mmv::ArticleScene s =
      std::get<mmv::ArticleScene>(mmv::loadSceneFile(std::string(MMVLAB_SOURCE_DIR) + "/scenes/mmv-slew.yaml"));
  const auto model = mmv::buildArticleModel(s);
  const auto& sys = model->getSystem();
  const auto& matter = model->getMatter();
  SimTK::State state = model->getReferenceState();
  for (int i = 0; i < state.getNU(); ++i) state.updU()[i] = 0.1 * std::sin(1.0 + i);
  SimTK::Matrix M;
  SimTK::Vector udot(state.getNU(), 0.0), tau, Mv;
  const SimTK::Vector_<SimTK::SpatialVec> no_body_forces(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
  const SimTK::Vector no_mobility_forces(state.getNU(), 0.0);
  for (auto _ : st) {
    state.invalidateAllCacheAtOrAbove(SimTK::Stage::Position);
    if (st.range(0) == 0) {
      sys.realize(state, SimTK::Stage::Acceleration);
    } else {
      sys.realize(state, SimTK::Stage::Velocity);
      if (st.range(0) == 1) matter.calcM(state, M);
      else if (st.range(0) == 2) matter.calcResidualForceIgnoringConstraints(state, no_mobility_forces, no_body_forces, udot, tau);
      else
        for (int k = 0; k < 8; ++k) matter.multiplyByM(state, udot, Mv);
    }
    benchmark::ClobberMemory();
  }
  st.counters["mobilities"] = state.getNU();
  const char* labels[] = {"full rhs", "mass matrix", "inverse dynamics", "8 x M v"};
  st.SetLabel(labels[st.range(0)]);
}
BENCHMARK(BM_RightHandSideParts)->DenseRange(0, 3)->Unit(benchmark::kMicrosecond);

}  // namespace

// Links in modal coordinates (links[i].modes, sim/time/modal_links.hpp) on the shipped
// slew scene's first 2 s, CVODE BDF at 1e-6 as the scene runs it: Arg 0 every hinge its
// own coordinate (the segment model), K > 0 each link carried by its first K modes. The
// whole simulate() as `mmvlab simulate` runs it (model, equilibrium, run, 1001 samples).
#include "sim/time/modal_links.hpp"

namespace {

void BM_SlewSceneModes(benchmark::State& st) {
  mmv::ArticleScene s = mmv::loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml");
  s.simulation.duration = 2.0;
  for (auto& l : s.article.links) l.modes = static_cast<int>(st.range(0));
  mmv::SimulationResult r;
  for (auto _ : st) r = mmv::simulate(s);
  st.counters["steps"] = r.steps;
  st.counters["evals"] = r.realizations;
  st.counters["stepping_s"] = r.stepping_seconds;
  st.counters["sampling_s"] = r.output_seconds;
  st.SetLabel(st.range(0) ? "modes per link" : "segment model");
}
BENCHMARK(BM_SlewSceneModes)->Arg(0)->Arg(2)->Arg(3)->Arg(4)->Unit(benchmark::kMillisecond)->Iterations(5);

// One right-hand side of the reduced model (ModalLinks::load without a sample's
// realization; compare BM_RightHandSideParts/0, the segment model's), slew scene at 3
// modes per link (12 reduced coordinates) in a bent, moving state.
void BM_ModalRightHandSide(benchmark::State& st) {
  mmv::ArticleScene s = mmv::loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml");
  for (auto& l : s.article.links) l.modes = 3;
  const auto model = mmv::buildArticleModel(s);
  SimTK::State state = model->getReferenceState();
  model->getSystem().realize(state, SimTK::Stage::Position);
  const mmv::ModalLinks modal(*model, s.article, state);
  std::vector<double> y(modal.size()), ydot(modal.size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = 0.01 * std::sin(1.0 + i);
  SimTK::State work = state;
  for (auto _ : st) {
    modal.load(1.3, y.data(), work, ydot.data(), false);
    benchmark::DoNotOptimize(ydot.data());
  }
  st.counters["coordinates"] = static_cast<double>(modal.size()) / 2;
}
BENCHMARK(BM_ModalRightHandSide)->Unit(benchmark::kMicrosecond);

// The residual M udot + c - f of the slew scene's segment model (8 segments a link, every
// coordinate moving) at a bent, moving state: /0 mmvlab's own pass
// (sim/model/tree_dynamics.hpp), /1 Simbody's (set q, u and time, realize to Dynamics,
// calcResidualForceIgnoringConstraints), what a modal run's right-hand side took before.
void BM_InverseDynamics(benchmark::State& st) {
  const mmv::ArticleScene s = mmv::loadArticleSceneFile(MMVLAB_SOURCE_DIR "/scenes/mmv-slew.yaml");
  const auto model = mmv::buildArticleModel(s, mmv::ModelUse::TimeRun);
  SimTK::State state = model->getReferenceState();
  const int n = model->getNumCoordinates();
  Eigen::VectorXd q(n), u(n), udot(n), r;
  SimTK::Vector knownUdot(state.getNU(), 0.0), residual;
  for (int i = 0; i < n; ++i) {
    q[i] = state.getQ()[model->getQIndex(i)] + 0.01 * std::sin(1.0 + i);
    u[i] = 0.1 * std::cos(2.0 + i), udot[i] = std::sin(3.0 + i);
    knownUdot[model->getUIndex(i)] = udot[i];
  }
  const mmv::TreeDynamics tree(*model, state);
  const SimTK::MultibodySystem& sys = model->getSystem();
  for (auto _ : st) {
    if (st.range(0) == 0) {
      tree.residual(1.3, q, u, udot, r);
      benchmark::DoNotOptimize(r.data());
    } else {
      for (int i = 0; i < n; ++i) state.updQ()[model->getQIndex(i)] = q[i], state.updU()[model->getUIndex(i)] = u[i];
      state.setTime(1.3);
      sys.realize(state, SimTK::Stage::Dynamics);
      model->getMatter().calcResidualForceIgnoringConstraints(state, sys.getMobilityForces(state, SimTK::Stage::Dynamics),
                                                              sys.getRigidBodyForces(state, SimTK::Stage::Dynamics),
                                                              knownUdot, residual);
      benchmark::DoNotOptimize(&residual[0]);
    }
  }
  st.counters["coordinates"] = n;
  st.SetLabel(st.range(0) == 0 ? "own" : "Simbody");
}
BENCHMARK(BM_InverseDynamics)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace


// A CSV program as every model build meets it (the builder makes the table's program
// from the scene's text): range(0) = 0, the same 20000-sample text each time (parsed
// once, then shared); 1, one of five texts in turn, more than the memo keeps, so every
// call parses.
void BM_CsvProfileProgram(benchmark::State& st) {
  std::vector<std::string> texts;
  for (int k = 0; k < 5; ++k) {
    std::string text = "time_s,x_m\n";
    for (int i = 0; i < 20000; ++i) text += std::to_string(1e-3 * i) + "," + std::to_string(1e-4 * std::sin(0.01 * i + k)) + "\n";
    texts.push_back(text);
  }
  std::size_t next = 0;
  for (auto _ : st) {
    const std::string& text = texts[st.range(0) ? next++ % texts.size() : 0];
    benchmark::DoNotOptimize(mmv::facility::csvProfile(text, "bench.csv"));
  }
}
BENCHMARK(BM_CsvProfileProgram)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

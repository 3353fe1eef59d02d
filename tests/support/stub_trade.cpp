#include "support/stub_trade.hpp"

#include <chrono>
#include <thread>

namespace mmv::testing {

TradeProblem stubTradeProblem(std::function<double(const SimulationSpec&, double)> x,
                              std::function<void(const SimulationSpec&, SimulationResult&)> finish,
                              double sleep_per_sample_s) {
  SimulationSpec spec;
  spec.duration = 1;
  spec.sample_rate_hz = 10;
  TradeProblem p = tradeProblemBase("stub", spec, 0);
  p.scorable = {"p"};
  p.scorable_kind = "point";
  p.has_segments = false;
  p.run = [x, finish, sleep_per_sample_s](const SimulationSpec& s, const RunFidelity&, const std::function<void(double)>& progress) {
    SimulationResult r;
    r.integrator = s.integrator;
    r.accuracy = s.accuracy;
    r.record.columns = {"time_s", "p_x_m"};
    r.record.scored = {{"p", {1}}};
    for (int k = 0; k <= 10; ++k) {
      if (sleep_per_sample_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(sleep_per_sample_s));
      r.record.rows.push_back({0.1 * k, x(s, 0.1 * k)});
      if (progress) progress(k / 10.0);
    }
    if (finish) finish(s, r);
    return r;
  };
  return p;
}

}  // namespace mmv::testing

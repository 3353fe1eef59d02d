#pragma once
/// Test support: a trade problem whose runs cost nothing and whose error is whatever the
/// test says, so the trade's and the accuracy contract's policies are tested without
/// depending on this machine's speed. One scored point "p" moving along x, 1 s at
/// 10 samples/s; `progress` is called at every sample (where budgets cut runs).

#include <functional>

#include "sim/time/trade.hpp"

namespace mmv::testing {

/// `x(spec, t)`: the point's position in a run with `spec`; `finish` may set the run's
/// reported costs and energies; `sleep_per_sample_s` > 0 makes each sample take that
/// long in wall time.
TradeProblem stubTradeProblem(std::function<double(const SimulationSpec&, double)> x,
                              std::function<void(const SimulationSpec&, SimulationResult&)> finish = {},
                              double sleep_per_sample_s = 0);

}  // namespace mmv::testing

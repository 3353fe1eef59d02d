#include "sim/core/integrators.hpp"

#include "sim/core/text.hpp"

#include <algorithm>

namespace mmv {

const std::vector<IntegratorInfo>& integratorTable() {
  using F = IntegratorInfo::Family;
  static const std::vector<IntegratorInfo> table{
      {"rk_merson", F::Simbody, false, false, "Runge-Kutta-Merson 4(5), error-controlled (default)"},
      {"rk_feldberg", F::Simbody, false, false, "Runge-Kutta-Fehlberg 4(5)"},
      {"rk3", F::Simbody, false, false, "Runge-Kutta 3(2)"},
      {"rk2", F::Simbody, false, false, "Runge-Kutta 2(1)"},
      {"cpodes", F::Simbody, true, false, "CPodes BDF with Newton (Simbody's, for stiff models)"},
      {"verlet", F::Simbody, false, false, "velocity Verlet, error-controlled"},
      {"semi_explicit_euler2", F::Simbody, false, false, "semi-explicit Euler with error control"},
      {"explicit_euler", F::Simbody, false, false, "explicit Euler with error control"},
      {"cvode_bdf", F::Sundials, true, true, "SUNDIALS CVODE BDF, dense Newton (stiff)"},
      {"cvode_adams", F::Sundials, false, true, "SUNDIALS CVODE Adams, fixed point (non-stiff)"},
      {"arkode_erk", F::Sundials, false, true, "SUNDIALS ARKODE explicit Runge-Kutta, order 4"},
      {"arkode_dirk", F::Sundials, true, true, "SUNDIALS ARKODE SDIRK, order 4, dense Newton (stiff)"},
      {"ida", F::Sundials, true, true, "SUNDIALS IDA: closures held as a stabilized index-2 DAE"},
  };
  return table;
}

const IntegratorInfo* findIntegrator(const std::string& name) {
  for (const auto& i : integratorTable())
    if (name == i.name) return &i;
  return nullptr;
}

bool isSundialsIntegrator(const std::string& name) {
  const IntegratorInfo* i = findIntegrator(name);
  return i && i->family == IntegratorInfo::Family::Sundials;
}

std::string integratorNames() {
  std::string out;
  for (const auto& i : integratorTable()) out += (out.empty() ? "" : ", ") + std::string(i.name);
  return out;
}

std::string integratorSuggestion(const std::string& name) {
  std::vector<std::string> names;
  for (const auto& i : integratorTable()) names.push_back(i.name);
  return didYouMean(name, names);
}

}  // namespace mmv

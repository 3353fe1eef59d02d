#include "sim/core/integrators.hpp"

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

#include <algorithm>

namespace mmv {

const std::vector<IntegratorInfo>& integratorTable() {
  using F = IntegratorInfo::Family;
  using I = IntegratorId;
  // name, id, family, implicit, absolute tolerance, projects closures, modal links, description
  static const std::vector<IntegratorInfo> table{
      {"rk_merson", I::RkMerson, F::Simbody, false, false, true, false, "Runge-Kutta-Merson 4(5), error-controlled (default)"},
      {"rk_feldberg", I::RkFeldberg, F::Simbody, false, false, true, false, "Runge-Kutta-Fehlberg 4(5)"},
      {"rk3", I::Rk3, F::Simbody, false, false, true, false, "Runge-Kutta 3(2)"},
      {"rk2", I::Rk2, F::Simbody, false, false, true, false, "Runge-Kutta 2(1)"},
      {"cpodes", I::CPodes, F::Simbody, true, false, true, false, "CPodes BDF with Newton (Simbody's, for stiff models)"},
      {"verlet", I::Verlet, F::Simbody, false, false, true, false, "velocity Verlet, error-controlled"},
      {"semi_explicit_euler2", I::SemiExplicitEuler2, F::Simbody, false, false, true, false,
       "semi-explicit Euler with error control"},
      {"explicit_euler", I::ExplicitEuler, F::Simbody, false, false, true, false, "explicit Euler with error control"},
      {"cvode_bdf", I::CvodeBdf, F::Sundials, true, true, false, true, "SUNDIALS CVODE BDF, dense Newton (stiff)"},
      {"cvode_adams", I::CvodeAdams, F::Sundials, false, true, false, true, "SUNDIALS CVODE Adams, fixed point (non-stiff)"},
      {"arkode_erk", I::ArkodeErk, F::Sundials, false, true, false, true, "SUNDIALS ARKODE explicit Runge-Kutta, order 4"},
      {"arkode_dirk", I::ArkodeDirk, F::Sundials, true, true, false, true,
       "SUNDIALS ARKODE SDIRK, order 4, dense Newton (stiff)"},
      {"ida", I::Ida, F::Sundials, true, true, true, false, "SUNDIALS IDA: closures held as a stabilized index-2 DAE"},
  };
  return table;
}

const IntegratorInfo* findIntegrator(const std::string& name) {
  for (const auto& i : integratorTable())
    if (name == i.name) return &i;
  return nullptr;
}

const IntegratorInfo& integratorInfo(const std::string& name) {
  const IntegratorInfo* i = findIntegrator(name);
  if (!i) throw InternalError("integrator '" + name + "' was not checked where it was given (the scene reader, a study)");
  return *i;
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

std::string integratorListing() {
  std::string simbody, sundials;
  for (const auto& i : integratorTable()) {
    std::string& list = i.family == IntegratorInfo::Family::Simbody ? simbody : sundials;
    list += (list.empty() ? "" : ", ") + std::string(i.name);
  }
  return simbody + " (Simbody's); " + sundials + " (SUNDIALS)";
}

}  // namespace mmv

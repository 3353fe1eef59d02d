#include "sim/time/external_stepper.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <filesystem>

#include "sim/core/errors.hpp"
#include "sim/core/plugins.hpp"

namespace mmv {

std::unique_ptr<ExternalStepper> makeSundialsStepper(const SimTK::MultibodySystem& system, SundialsMethod method,
                                                     double rtol, double atol, const ReducedCoordinates* reduced) {
#ifdef MMVLAB_SUNDIALS_PLUGIN
  const std::vector<std::string> candidates = pluginCandidates("libmmvlab_sundials.so", MMVLAB_SUNDIALS_PLUGIN);
#else
  const std::vector<std::string> candidates = pluginCandidates("libmmvlab_sundials.so", "");
#endif
  std::string tried;
  for (const auto& path : candidates) {
    // Loaded once per process and kept: the steppers it creates run its code.
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      tried += (tried.empty() ? "" : "; ") + path + " (" + ::dlerror() + ")";
      continue;
    }
    // _v2: the factory that takes reduced coordinates (an older plugin lacks it).
    auto create = reinterpret_cast<CreateStepper>(::dlsym(handle, "mmv_create_sundials_stepper_v2"));
    if (!create) throw UnavailableError(path + ": no mmv_create_sundials_stepper_v2 (a plugin from an older build?)");
    ExternalStepper* stepper = create(&system, static_cast<int>(method), rtol, atol, reduced);
    MMV_DEMAND(stepper != nullptr);  // every SundialsMethod has a stepper
    return std::unique_ptr<ExternalStepper>(stepper);
  }
  throw UnavailableError("the SUNDIALS integrators need libmmvlab_sundials.so: tried " + tried);
}

}  // namespace mmv

#include "sim/model/reduced_motions.hpp"

namespace mmv {
namespace {

/// A mobilizer whose accelerations are a state variable of the run.
class GivenAcceleration : public SimTK::Motion::Custom::Implementation {
 public:
  GivenAcceleration(const SimTK::SimbodyMatterSubsystem& matter, SimTK::MobilizedBodyIndex mobod,
                    SimTK::Measure_<SimTK::Vector>::Variable udot)
      : matter_(&matter), mobod_(mobod), udot_(udot) {}
  GivenAcceleration* clone() const override { return new GivenAcceleration(*this); }
  SimTK::Motion::Level getLevel(const SimTK::State&) const override { return SimTK::Motion::Acceleration; }
  void calcPrescribedAcceleration(const SimTK::State& s, int nu, SimTK::Real* udot) const override {
    const SimTK::Vector& a = udot_.getValue(s);
    const int u0 = matter_->getMobilizedBody(mobod_).getFirstUIndex(s);
    for (int i = 0; i < nu; ++i) udot[i] = a[u0 + i];
  }

 private:
  const SimTK::SimbodyMatterSubsystem* matter_;
  SimTK::MobilizedBodyIndex mobod_;
  SimTK::Measure_<SimTK::Vector>::Variable udot_;
};

}  // namespace

void ReducedMotions::addTo(SimTK::SimbodyMatterSubsystem& matter, const std::vector<SimTK::MobilizedBodyIndex>& mobods,
                           int nu) {
  mobods_ = mobods;
  // Changing the accelerations invalidates Dynamics, where Simbody asks a Motion for them.
  udot_ = SimTK::Measure_<SimTK::Vector>::Variable(matter, SimTK::Stage::Dynamics, SimTK::Vector(nu, 0.0));
  for (const auto ix : mobods_) {
    SimTK::Motion::Custom motion(matter.updMobilizedBody(ix), new GivenAcceleration(matter, ix, udot_));
    motion.setDisabledByDefault(true);
  }
}

void ReducedMotions::enable(const SimTK::SimbodyMatterSubsystem& matter, SimTK::State& s) const {
  for (const auto ix : mobods_) matter.getMobilizedBody(ix).getMotion().enable(s);
}

void ReducedMotions::setAccelerations(SimTK::State& s, const SimTK::Vector& udot) const { udot_.setValue(s, udot); }

}  // namespace mmv

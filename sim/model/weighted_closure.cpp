#include "sim/model/weighted_closure.hpp"

#include <map>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

using SimTK::ConstrainedBodyIndex;
using SimTK::SpatialVec;
using SimTK::Transform;
using SimTK::Vec3;

class WeightedClosure : public SimTK::Constraint::Custom::Implementation {
 public:
  WeightedClosure(SimTK::SimbodyMatterSubsystem& matter, const Closure& c, const Vec3& n_B)
      : Implementation(matter, 1, 0, 0), n_B_(n_B), station_b_(c.station_b) {
    b_ = addConstrainedBody(matter.getMobilizedBody(c.mobod_b));
    std::map<SimTK::MobilizedBodyIndex, ConstrainedBodyIndex> added{{c.mobod_b, b_}};  // each body once
    for (const WeightedPoint& p : c.points_a) {
      auto it = added.find(p.mobod);
      if (it == added.end()) it = added.emplace(p.mobod, addConstrainedBody(matter.getMobilizedBody(p.mobod))).first;
      points_.push_back({it->second, p.station_B, p.weight});
    }
  }
  Implementation* clone() const override { return new WeightedClosure(*this); }

  void calcPositionErrors(const SimTK::State&, const SimTK::Array_<Transform, ConstrainedBodyIndex>& X_AB,
                          const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, SimTK::Array_<SimTK::Real>& perr) const override {
    Vec3 pa(0);
    for (const Term& t : points_) pa += t.weight * findStationLocation(X_AB, t.body, t.station);
    const Vec3 n = getBodyRotation(X_AB, b_) * n_B_;
    perr[0] = ~n * (pa - findStationLocation(X_AB, b_, station_b_));
  }

  void calcPositionDotErrors(const SimTK::State& s, const SimTK::Array_<SpatialVec, ConstrainedBodyIndex>& V_AB,
                             const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, SimTK::Array_<SimTK::Real>& pverr) const override {
    const Vec3 d = pointA(s) - findStationLocationFromState(s, b_, station_b_);
    Vec3 va(0);
    for (const Term& t : points_) va += t.weight * findStationVelocity(s, V_AB, t.body, t.station);
    const Vec3 n = getBodyRotationFromState(s, b_) * n_B_, w = getBodyAngularVelocity(V_AB, b_);
    pverr[0] = ~(w % n) * d + ~n * (va - findStationVelocity(s, V_AB, b_, station_b_));
  }

  void calcPositionDotDotErrors(const SimTK::State& s, const SimTK::Array_<SpatialVec, ConstrainedBodyIndex>& A_AB,
                                const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>&, SimTK::Array_<SimTK::Real>& paerr) const override {
    const Vec3 d = pointA(s) - findStationLocationFromState(s, b_, station_b_);
    Vec3 va(0), aa(0);
    for (const Term& t : points_) {
      va += t.weight * findStationVelocityFromState(s, t.body, t.station);
      aa += t.weight * findStationAcceleration(s, A_AB, t.body, t.station);
    }
    const Vec3 n = getBodyRotationFromState(s, b_) * n_B_, w = getBodyAngularVelocityFromState(s, b_);
    const Vec3 alpha = getBodyAngularAcceleration(A_AB, b_);
    const Vec3 dv = va - findStationVelocityFromState(s, b_, station_b_), da = aa - findStationAcceleration(s, A_AB, b_, station_b_);
    paerr[0] = ~(alpha % n + w % (w % n)) * d + 2 * ~(w % n) * dv + ~n * da;
  }

  void addInPositionConstraintForces(const SimTK::State& s, const SimTK::Array_<SimTK::Real>& multipliers,
                                     SimTK::Array_<SpatialVec, ConstrainedBodyIndex>& forces,
                                     SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>&) const override {
    const Vec3 f = multipliers[0] * (getBodyRotationFromState(s, b_) * n_B_);
    for (const Term& t : points_) addInStationForce(s, t.body, t.station, t.weight * f, forces);
    // On B at the point coincident with A: its force and the torque of n's turn.
    const Vec3 coincident_B = ~getBodyTransformFromState(s, b_) * pointA(s);
    addInStationForce(s, b_, coincident_B, -f, forces);
  }

 private:
  struct Term {
    ConstrainedBodyIndex body;
    Vec3 station;
    double weight;
  };
  Vec3 pointA(const SimTK::State& s) const {
    Vec3 pa(0);
    for (const Term& t : points_) pa += t.weight * findStationLocationFromState(s, t.body, t.station);
    return pa;
  }
  Vec3 n_B_, station_b_;
  ConstrainedBodyIndex b_;
  std::vector<Term> points_;
};

}  // namespace

void addWeightedClosure(SimTK::SimbodyMatterSubsystem& matter, const Closure& c, const SimTK::State& at) {
  MMV_DEMAND(!c.to_ground && c.directions.size() == 1 && !c.points_a.empty());
  const Vec3 n_B = ~matter.getMobilizedBody(c.mobod_b).getBodyRotation(at) * c.directions[0];
  SimTK::Constraint::Custom(new WeightedClosure(matter, c, n_B));
}

}  // namespace mmv

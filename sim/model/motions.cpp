#include "sim/model/motions.hpp"


namespace mmv {
namespace {

/// A locked joint that follows a slew: q(t) from facility/slews.hpp.
class SlewMotion : public SimTK::Motion::Custom::Implementation {
 public:
  SlewMotion(facility::Slew slew, double start) : slew_(slew), start_(start) {}
  SlewMotion* clone() const override { return new SlewMotion(*this); }
  SimTK::Motion::Level getLevel(const SimTK::State&) const override { return SimTK::Motion::Position; }
  void calcPrescribedPosition(const SimTK::State& s, int, SimTK::Real* q) const override { q[0] = at(s).angle; }
  void calcPrescribedPositionDot(const SimTK::State& s, int, SimTK::Real* qd) const override { qd[0] = at(s).rate; }
  void calcPrescribedPositionDotDot(const SimTK::State& s, int, SimTK::Real* qdd) const override {
    qdd[0] = at(s).acceleration;
  }

 private:
  facility::SlewState at(const SimTK::State& s) const { return slew_.at(s.getTime() - start_); }
  facility::Slew slew_;
  double start_;
};

/// The table following a motion program (facility/table_programs.hpp).
class TableProgramMotion : public SimTK::Motion::Custom::Implementation {
 public:
  explicit TableProgramMotion(std::shared_ptr<const facility::TableProgram> p) : p_(std::move(p)) {}
  TableProgramMotion* clone() const override { return new TableProgramMotion(*this); }
  SimTK::Motion::Level getLevel(const SimTK::State&) const override { return SimTK::Motion::Position; }
  void calcPrescribedPosition(const SimTK::State& s, int, SimTK::Real* q) const override { q[0] = p_->position(s.getTime()); }
  void calcPrescribedPositionDot(const SimTK::State& s, int, SimTK::Real* qd) const override { qd[0] = p_->velocity(s.getTime()); }
  void calcPrescribedPositionDotDot(const SimTK::State& s, int, SimTK::Real* qdd) const override {
    qdd[0] = p_->acceleration(s.getTime());
  }

 private:
  std::shared_ptr<const facility::TableProgram> p_;
};

}  // namespace

PrescribedMotion prescribeTableProgram(SimTK::MobilizedBody& mobod, std::shared_ptr<const facility::TableProgram> program) {
  SimTK::Motion::Custom(mobod, new TableProgramMotion(program));
  return {[program](double t) { return program->position(t); }, [program](double t) { return program->velocity(t); },
          [program](double t) { return program->acceleration(t); }};
}

PrescribedMotion prescribeSlew(SimTK::MobilizedBody& mobod, const facility::Slew& slew, double start_s) {
  SimTK::Motion::Custom(mobod, new SlewMotion(slew, start_s));
  return {[slew, start_s](double t) { return slew.at(t - start_s).angle; },
          [slew, start_s](double t) { return slew.at(t - start_s).rate; },
          [slew, start_s](double t) { return slew.at(t - start_s).acceleration; }};
}

PrescribedMotion prescribeRest(SimTK::MobilizedBody& mobod) {
  SimTK::Motion::Steady(mobod, 0.0);
  return {{}, {}, [](double) { return 0.0; }};
}

}  // namespace mmv

#pragma once
// Scenes built in code for the tests: uniform links with explicit A and I so the
// analytic references apply exactly.

#include <cmath>
#include <string>

#include "sim/scene/scene.hpp"

namespace mmv::testing {

struct Beam {
  double length = 1.0;        // m
  double density = 7800.0;    // kg/m^3
  double youngs = 2.0e11;     // Pa
  double area = 1e-4;         // m^2
  double second_moment = 1e-9;  // m^4
  double massPerLength() const { return density * area; }
  double bendingStiffness() const { return youngs * second_moment; }
};

/// An article of one link on a locked base joint. direction_deg = 0: the link points
/// along +x (horizontal, gravity along -y); -90: it hangs down.
inline ArticleScene cantileverScene(const Beam& b, int segments, double gravity, double direction_deg = 0.0,
                             double tip_mass = 0.0, bool rigid = false) {
  ArticleScene s;
  s.name = "cantilever";
  s.source = "<test>";
  s.gravity = {0, -gravity, 0};
  s.article.materials.push_back({"m", b.density, b.youngs});
  Section sec;
  sec.name = "s";
  sec.shape = SectionShape::Explicit;
  sec.explicit_area = b.area;
  sec.explicit_second_moment = b.second_moment;
  s.article.sections.push_back(sec);
  s.article.base.direction = direction_deg * M_PI / 180.0;
  JointSpec j;
  j.name = "joint1";
  j.parent = "base";
  j.hold = JointHold::Locked;
  s.article.joints.push_back(j);
  LinkSpec l;
  l.name = "link1";
  l.joint = "joint1";
  l.material = "m";
  l.section = "s";
  l.length = b.length;
  l.segments = segments;
  l.rigid = rigid;
  if (tip_mass > 0) l.tip_mass = LumpedMass{tip_mass, 0.0};
  s.article.links.push_back(l);
  return s;
}

/// A hanging chain of n rigid links joined by free pins, hanging from a free pin.
/// Each link: length total/n, mass per length mu. Optional point masses at every
/// joint (on the parent side) and at the last tip.
inline ArticleScene chainScene(int n, double total_length, double mass_per_length, double gravity,
                        double joint_mass = 0.0, double tip_mass = 0.0) {
  ArticleScene s;
  s.name = "chain";
  s.source = "<test>";
  s.gravity = {0, -gravity, 0};
  s.article.materials.push_back({"m", mass_per_length / 1e-4, 1e9});
  Section sec;
  sec.name = "s";
  sec.shape = SectionShape::Explicit;
  sec.explicit_area = 1e-4;
  sec.explicit_second_moment = 1e-10;
  s.article.sections.push_back(sec);
  s.article.base.direction = -M_PI / 2;
  for (int i = 0; i < n; ++i) {
    JointSpec j;
    j.name = "j" + std::to_string(i + 1);
    j.parent = i == 0 ? "base" : "l" + std::to_string(i);
    j.hold = JointHold::Free;
    if (i > 0 && joint_mass > 0) j.torquer = LumpedMass{joint_mass, 0.0};
    s.article.joints.push_back(j);
    LinkSpec l;
    l.name = "l" + std::to_string(i + 1);
    l.joint = j.name;
    l.material = "m";
    l.section = "s";
    l.length = total_length / n;
    l.rigid = true;
    if (i == n - 1 && tip_mass > 0) l.tip_mass = LumpedMass{tip_mass, 0.0};
    s.article.links.push_back(l);
  }
  return s;
}

/// The default article (as `mmvlab scene` writes it: no integrator or fidelity named) at
/// `segments` per link on the base table under a 0.5-10 Hz random program of 1 mm RMS:
/// issue 37's user scene (169 s as every hinge under CPodes), `duration` s of it.
inline ArticleScene templateOnTheTable(int segments, double duration) {
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, segments);
  s.article.base.type = BaseType::Table;
  s.article.base.table_mass = 100;
  TableMotion m;
  m.type = TableMotion::Type::Random;
  m.rms = 0.001, m.from_hz = 0.5, m.to_hz = 10, m.duration = 10, m.seed = 1;
  s.article.base.motion = m;
  s.simulation.duration = duration;
  return s;
}

}  // namespace mmv::testing

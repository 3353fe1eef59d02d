#include "article/section.hpp"

#include <algorithm>
#include <cmath>

namespace mmv {

double sectionArea(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle: return s.b * s.h;
    case SectionShape::RectangularTube: return 2.0 * s.t * (s.b + s.h) - 4.0 * s.t * s.t;
    case SectionShape::RoundRod: return M_PI * s.radius * s.radius;
    case SectionShape::Explicit: return s.explicit_area;
  }
  return 0;
}

namespace {

/// (b h^3 - (b - 2t)(h - 2t)^3) / 12, the tube's second moment about the axis along b,
/// expanded in u = 2t and evaluated by Horner's rule: the two nearly equal terms of the
/// closed form cancel to 0 for a wall far thinner than the section (1e-20 m in 2 cm: E*I
/// = 0 and an internal error downstream); the expansion keeps the wall's first-order term
/// u (3 b h^2 + h^3) exact and is b h^3 / 12 again when the wall fills the height (u = h).
double tubeSecondMoment(double b, double h, double t) {
  const double u = 2 * t;
  return u * ((3 * b * h * h + h * h * h) - u * ((3 * b * h + 3 * h * h) - u * ((b + 3 * h) - u))) / 12.0;
}

}  // namespace

double sectionSecondMoment(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle: return s.b * std::pow(s.h, 3) / 12.0;
    case SectionShape::RectangularTube: return tubeSecondMoment(s.b, s.h, s.t);
    case SectionShape::RoundRod: return M_PI * std::pow(s.radius, 4) / 4.0;
    case SectionShape::Explicit: return s.explicit_second_moment;
  }
  return 0;
}

double sectionSecondMomentOut(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle: return s.h * std::pow(s.b, 3) / 12.0;
    case SectionShape::RectangularTube: return tubeSecondMoment(s.h, s.b, s.t);
    case SectionShape::RoundRod: return M_PI * std::pow(s.radius, 4) / 4.0;
    case SectionShape::Explicit: return s.explicit_second_moment_out;
  }
  return 0;
}

double sectionTorsionConstant(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle: {
      const double a = std::max(s.b, s.h), c = std::min(s.b, s.h), r = c / a;
      return a * std::pow(c, 3) * (1.0 / 3.0 - 0.21 * r * (1 - std::pow(r, 4) / 12.0));
    }
    case SectionShape::RectangularTube:
      return 2 * s.t * std::pow(s.b - s.t, 2) * std::pow(s.h - s.t, 2) / (s.b + s.h - 2 * s.t);
    case SectionShape::RoundRod: return M_PI * std::pow(s.radius, 4) / 2.0;
    case SectionShape::Explicit: return s.explicit_torsion_constant;
  }
  return 0;
}

double sectionFibreDistance(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle:
    case SectionShape::RectangularTube: return s.h / 2;
    case SectionShape::RoundRod: return s.radius;
    case SectionShape::Explicit: return s.explicit_fibre_distance;
  }
  return 0;
}

double sectionFibreDistanceOut(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle:
    case SectionShape::RectangularTube: return s.b / 2;
    case SectionShape::RoundRod: return s.radius;
    case SectionShape::Explicit: return s.explicit_fibre_distance_out;
  }
  return 0;
}

double sectionTorsionShearPerTorque(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle: {
      const double a = std::max(s.b, s.h) / 2, c = std::min(s.b, s.h) / 2, r = c / a;
      return 3.0 / (8 * a * c * c) * (1 + r * (0.6095 + r * (0.8865 + r * (-1.8023 + r * 0.9100))));
    }
    case SectionShape::RectangularTube: return 1.0 / (2 * (s.b - s.t) * (s.h - s.t) * s.t);
    case SectionShape::RoundRod: return 2.0 / (M_PI * std::pow(s.radius, 3));
    case SectionShape::Explicit: return 0;
  }
  return 0;
}

double sectionGyrationSquared(const Section& s) { return sectionSecondMoment(s) / sectionArea(s); }

const char* sectionShapeName(SectionShape shape) {
  switch (shape) {
    case SectionShape::Rectangle: return "rectangle";
    case SectionShape::RectangularTube: return "rectangular_tube";
    case SectionShape::RoundRod: return "round_rod";
    case SectionShape::Explicit: return "explicit";
  }
  return "?";
}

}  // namespace mmv

#pragma once
/// Materials and beam cross-sections of the test articles.
///
/// Bending is in the plane of motion (the x-y plane of the article). For every
/// section, `h` is the depth in that plane (the bending direction) and `b` the width
/// out of plane, so I = b h^3 / 12 for a solid rectangle (MMV report, Table 1).

#include <string>

namespace mmv {

/// An isotropic linear-elastic material.
struct Material {
  std::string name;
  double density = 0;         ///< rho in kg/m^3, must be > 0.
  double youngs_modulus = 0;  ///< E in Pa, must be > 0.
};

enum class SectionShape { Rectangle, RectangularTube, RoundRod, Explicit };

/// A cross-section given by its shape and dimensions (m), or explicitly by A and I.
struct Section {
  std::string name;
  SectionShape shape = SectionShape::Explicit;
  double b = 0;       ///< width out of the bending plane in m (rectangle, tube).
  double h = 0;       ///< depth in the bending plane in m (rectangle, tube).
  double t = 0;       ///< wall thickness in m (tube), 0 < 2t < min(b, h).
  double radius = 0;  ///< radius in m (round rod).
  double explicit_area = 0;           ///< A in m^2 (explicit shape).
  double explicit_second_moment = 0;  ///< I in m^4 about the out-of-plane axis (explicit).
};

/// Cross-section area A in m^2. A = b h, 2 t (b + h) - 4 t^2, or pi R^2.
double sectionArea(const Section& s);
/// Second moment of area I in m^4 for bending in the plane of motion.
/// I = b h^3/12, [b h^3 - (b - 2t)(h - 2t)^3]/12, or pi R^4/4.
double sectionSecondMoment(const Section& s);
/// Squared radius of gyration of the section about the bending axis, I/A, in m^2.
double sectionGyrationSquared(const Section& s);

const char* sectionShapeName(SectionShape shape);

}  // namespace mmv

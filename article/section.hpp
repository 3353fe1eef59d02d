#pragma once
/// Materials and beam cross-sections of the test articles.
///
/// Bending is in the plane of motion (the x-y plane of the article). For every
/// section, `h` is the depth in that plane (the bending direction) and `b` the width
/// out of plane, so I = b h^3 / 12 for a solid rectangle (MMV report, Table 1).
/// The spatial model (docs/spatial.md) also bends the section out of the plane (about
/// the link's in-plane normal, I_out: b and h swap roles) and twists it (St Venant
/// torsion, G J); the report gives neither, so the formulas below are stated.

#include <string>

namespace mmv {

/// An isotropic linear-elastic material.
struct Material {
  std::string name;
  double density = 0;         ///< rho in kg/m^3, must be > 0.
  double youngs_modulus = 0;  ///< E in Pa, must be > 0.
  /// G in Pa (torsion, spatial model only): given, or E / (2 (1 + nu)) from a given
  /// Poisson's ratio; 0 when the scene gives neither.
  double shear_modulus = 0;
  /// Allowables (docs/strength.md), Pa; 0 when the scene gives none (a stress is then
  /// stated with "no allowable: margin not judged").
  double yield_strength = 0;     ///< the yield or proportional-limit stress.
  double ultimate_strength = 0;  ///< the ultimate (failure) stress, >= yield_strength.
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
  double explicit_second_moment_out = 0;  ///< I_out in m^4 (explicit; 0: not given).
  double explicit_torsion_constant = 0;   ///< J in m^4 (explicit; 0: not given).
  double explicit_fibre_distance = 0;      ///< c in m, in the plane (explicit; 0: not given).
  double explicit_fibre_distance_out = 0;  ///< c_out in m, out of it (explicit; 0: not given).
};

/// Cross-section area A in m^2. A = b h, 2 t (b + h) - 4 t^2, or pi R^2.
double sectionArea(const Section& s);
/// Second moment of area I in m^4 for bending in the plane of motion.
/// I = b h^3/12, [b h^3 - (b - 2t)(h - 2t)^3]/12, or pi R^4/4.
double sectionSecondMoment(const Section& s);
/// Second moment of area in m^4 for bending out of the plane of motion (about the
/// link's in-plane normal): h b^3/12, [h b^3 - (h - 2t)(b - 2t)^3]/12, pi R^4/4, or
/// the explicit value (0 when not given).
double sectionSecondMomentOut(const Section& s);
/// St Venant torsion constant J in m^4 (G J is the torsional stiffness):
///  - solid rectangle, sides a >= c: J = a c^3 [1/3 - 0.21 (c/a) (1 - c^4 / (12 a^4))]
///    (Roark's Formulas for Stress and Strain, table of torsion constants; within
///    0.5 % of the exact series for every aspect ratio; 0.1406 a^4 for a square);
///  - rectangular tube, Bredt's thin-walled closed section on the wall's midline:
///    J = 4 A_m^2 t / p_m = 2 t (b - t)^2 (h - t)^2 / (b + h - 2t);
///  - round rod: J = pi R^4 / 2 (exact);
///  - explicit: the given value (0 when not given).
double sectionTorsionConstant(const Section& s);
/// Distance in m from the neutral axis to the extreme fibre for bending in the plane of
/// motion: h / 2 (rectangle, tube), R (rod), or the explicit value (0 when not given).
double sectionFibreDistance(const Section& s);
/// The same for bending out of the plane: b / 2, R, or the explicit value.
double sectionFibreDistanceOut(const Section& s);
/// The largest torsional shear stress per unit torque, Pa per N*m, at the surface:
///  - round rod: R / J = 2 / (pi R^3) (exact);
///  - rectangular tube: Bredt's 1 / (2 A_m t), A_m = (b - t)(h - t) the area inside the
///    wall's midline (uniform over a thin wall);
///  - solid rectangle, sides 2a >= 2c: 3 / (8 a c^2) (1 + 0.6095 r + 0.8865 r^2 -
///    1.8023 r^3 + 0.9100 r^4), r = c / a, at the middle of the long sides (Roark's
///    Formulas for Stress and Strain, torsion of a solid rectangle; 0.601 / a^3 for a
///    square, the series' 1 / (0.208 s^3));
///  - explicit: 0 (not known: the torsional shear is not recovered).
double sectionTorsionShearPerTorque(const Section& s);
/// Squared radius of gyration of the section about the bending axis, I/A, in m^2.
double sectionGyrationSquared(const Section& s);

const char* sectionShapeName(SectionShape shape);

}  // namespace mmv

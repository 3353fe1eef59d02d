#include "article/flexible_link.hpp"

#include <stdexcept>

namespace mmv {

LinkDiscretization discretizeLink(double length, double mass_per_length, double bending_stiffness,
                                  int segments, bool rigid) {
  // The scene reader checks these with the scene's line and column; this guards callers in code.
  if (!(length > 0 && mass_per_length > 0)) throw std::invalid_argument("discretizeLink: length and mass per length must be > 0");
  LinkDiscretization d;
  auto addPiece = [&](double x0, double l) {
    LinkPiece p;
    p.x_start = x0;
    p.length = l;
    p.mass = mass_per_length * l;
    p.inertia_zz_about_com = p.mass * l * l / 12.0;
    d.pieces.push_back(p);
  };
  if (rigid) {
    addPiece(0.0, length);
    return d;
  }
  if (!(segments >= 1 && bending_stiffness > 0))
    throw std::invalid_argument("discretizeLink: a flexible link needs segments >= 1 and E*I > 0");
  const double h = length / segments;
  addPiece(0.0, 0.5 * h);
  for (int k = 1; k < segments; ++k) addPiece((k - 0.5) * h, h);
  addPiece(length - 0.5 * h, 0.5 * h);
  for (int k = 1; k <= segments; ++k) {
    d.hinge_x.push_back((k - 0.5) * h);
    d.hinge_stiffness.push_back(bending_stiffness / h);
  }
  return d;
}

}  // namespace mmv

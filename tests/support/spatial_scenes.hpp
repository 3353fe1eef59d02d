#pragma once
// Spatial-model test scenes (docs/spatial.md), shared by the spatial tests.
#include "sim/scene/scene.hpp"
#include "support/scenes.hpp"

namespace mmv::testing {

/// A horizontal cantilever (root clamped by a locked joint), no gravity, spatial model:
/// support/scenes.hpp's cantilever with section `sec` and shear modulus G.
inline ArticleScene spatialCantilever(const Section& sec, double density, double E, double G, double length,
                                      int segments, double tip_mass = 0, double tip_rotary = 0) {
  Beam b;
  b.density = density;
  b.youngs = E;
  b.length = length;
  ArticleScene s = cantileverScene(b, segments, 0.0, 0.0, tip_mass);
  s.name = "spatial cantilever";
  s.article.materials[0].shear_modulus = G;
  const std::string name = s.article.sections[0].name;
  s.article.sections[0] = sec;
  s.article.sections[0].name = name;
  if (tip_mass > 0) s.article.links[0].tip_mass->rotary_inertia = tip_rotary;
  s.article.model = ArticleModel::Spatial;
  return s;
}

/// The default article in the spatial model; `segments` > 0 replaces every flexible
/// link's count.
inline ArticleScene spatialDefault(int segments = 0) {
  ArticleScene s = loadDefaultScene();
  s.article.model = ArticleModel::Spatial;
  if (segments > 0)
    for (auto& l : s.article.links) l.segments = segments;
  return s;
}

/// An explicit section: area, in-plane and out-of-plane second moments, torsion constant.
inline Section explicitSection(double area, double i_in, double i_out, double j) {
  Section s;
  s.shape = SectionShape::Explicit;
  s.explicit_area = area;
  s.explicit_second_moment = i_in;
  s.explicit_second_moment_out = i_out;
  s.explicit_torsion_constant = j;
  return s;
}

}  // namespace mmv::testing

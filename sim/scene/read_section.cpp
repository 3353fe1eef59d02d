// Scene materials and cross-sections (article/section.hpp): the section's shape keys, and
// a material's elastic constants (the shear modulus, or Poisson's ratio, for the spatial model).
#include "sim/scene/reader_util.hpp"

namespace mmv::scene_detail {

Section readSection(const YamlReader& r, const std::string& name, const YAML::Node& n,
                    const std::string& path) {
  auto m = r.mapping(n, path, {"shape", "b", "h", "t", "radius", "area", "second_moment", "second_moment_out",
                               "torsion_constant", "fibre_distance", "fibre_distance_out"});
  Section s;
  s.name = name;
  const YAML::Node& shape = r.require(m, n, path, "shape");
  const std::string kind = r.text(shape, path + ".shape");
  auto need = [&](const char* key) -> const YAML::Node& { return r.require(m, n, path, key); };
  auto forbid = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (m.count(k))
        r.fail(m.at(k).Mark(), path + "." + k + " does not apply to shape '" + kind + "'");
  };
  if (kind == "rectangle") {
    s.shape = SectionShape::Rectangle;
    forbid({"t", "radius", "area", "second_moment", "second_moment_out", "torsion_constant", "fibre_distance",
            "fibre_distance_out"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
  } else if (kind == "rectangular_tube") {
    s.shape = SectionShape::RectangularTube;
    forbid({"radius", "area", "second_moment", "second_moment_out", "torsion_constant", "fibre_distance",
            "fibre_distance_out"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
    s.t = r.positive(need("t"), path + ".t", " m");
    if (2 * s.t >= std::min(s.b, s.h))
      r.fail(need("t").Mark(), path + ".t must be < min(b, h)/2 m so the tube has a hole (got " +
                                   need("t").Scalar() + ")");
  } else if (kind == "round_rod") {
    s.shape = SectionShape::RoundRod;
    forbid({"b", "h", "t", "area", "second_moment", "second_moment_out", "torsion_constant", "fibre_distance",
            "fibre_distance_out"});
    s.radius = r.positive(need("radius"), path + ".radius", " m");
  } else if (kind == "explicit") {
    s.shape = SectionShape::Explicit;
    forbid({"b", "h", "t", "radius"});
    s.explicit_area = r.positive(need("area"), path + ".area", " m^2");
    s.explicit_second_moment = r.positive(need("second_moment"), path + ".second_moment", " m^4");
    if (m.count("second_moment_out"))
      s.explicit_second_moment_out = r.positive(m.at("second_moment_out"), path + ".second_moment_out", " m^4");
    if (m.count("torsion_constant"))
      s.explicit_torsion_constant = r.positive(m.at("torsion_constant"), path + ".torsion_constant", " m^4");
    // The extreme fibres' distances: without them an explicit section's stress is not
    // recovered (docs/strength.md), and every stress line says so.
    if (m.count("fibre_distance"))
      s.explicit_fibre_distance = r.positive(m.at("fibre_distance"), path + ".fibre_distance", " m");
    if (m.count("fibre_distance_out"))
      s.explicit_fibre_distance_out = r.positive(m.at("fibre_distance_out"), path + ".fibre_distance_out", " m");
  } else {
    r.fail(shape.Mark(), path + ".shape: unknown shape '" + kind +
                             "' (known: rectangle, rectangular_tube, round_rod, explicit)");
  }
  return s;
}

Material readMaterial(const YamlReader& r, const std::string& name, const YAML::Node& node, const std::string& path) {
  auto mm = r.mapping(node, path, {"density", "youngs_modulus", "shear_modulus", "poisson_ratio", "yield_strength",
                                   "ultimate_strength"});
  Material mat;
  mat.name = name;
  mat.density = r.positive(r.require(mm, node, path, "density"), path + ".density", " kg/m^3");
  mat.youngs_modulus =
      r.positive(r.require(mm, node, path, "youngs_modulus"), path + ".youngs_modulus", " Pa");
  if (mm.count("shear_modulus") && mm.count("poisson_ratio"))
    r.fail(mm.at("poisson_ratio").Mark(), path + ": give shear_modulus or poisson_ratio, not both");
  if (mm.count("shear_modulus"))
    mat.shear_modulus = r.positive(mm.at("shear_modulus"), path + ".shear_modulus", " Pa");
  if (mm.count("poisson_ratio")) {
    const double nu = r.number(mm.at("poisson_ratio"), path + ".poisson_ratio");
    if (!(nu > -1 && nu < 0.5))
      r.fail(mm.at("poisson_ratio").Mark(), path + ".poisson_ratio must be in (-1, 0.5) for an isotropic solid (got " +
                    mm.at("poisson_ratio").Scalar() + ")");
    mat.shear_modulus = mat.youngs_modulus / (2 * (1 + nu));
  }
  if (mm.count("yield_strength"))
    mat.yield_strength = r.positive(mm.at("yield_strength"), path + ".yield_strength", " Pa");
  if (mm.count("ultimate_strength"))
    mat.ultimate_strength = r.positive(mm.at("ultimate_strength"), path + ".ultimate_strength", " Pa");
  if (mat.yield_strength > 0 && mat.ultimate_strength > 0 && mat.yield_strength > mat.ultimate_strength)
    r.fail(mm.at("yield_strength").Mark(), path + ".yield_strength " + mm.at("yield_strength").Scalar() +
                                               " Pa exceeds its ultimate_strength " + mm.at("ultimate_strength").Scalar() +
                                               " Pa: a material yields before it fails");
  return mat;
}

StrengthFactors readStrengthFactors(const YamlReader& r, const YAML::Node& n) {
  auto m = r.mapping(n, "strength", {"yield_factor", "ultimate_factor"});
  StrengthFactors f;
  f.given = true;
  auto factor = [&](const char* key, double& out) {
    if (!m.count(key)) return;
    const std::string path = std::string("strength.") + key;
    out = r.number(m.at(key), path);
    if (!(out >= 1.0))
      r.fail(m.at(key).Mark(), path + " must be >= 1 (a factor of safety below 1 accepts a stress above the allowable; got " +
                                   m.at(key).Scalar() + ")");
  };
  factor("yield_factor", f.yield_factor);
  factor("ultimate_factor", f.ultimate_factor);
  return f;
}

}  // namespace mmv::scene_detail

// Scene materials and cross-sections (article/section.hpp): the section's shape keys, and
// a material's elastic constants (the shear modulus, or Poisson's ratio, for the spatial model).
#include "sim/scene/reader_util.hpp"

namespace mmv::scene_detail {

Section readSection(const YamlReader& r, const std::string& name, const YAML::Node& n,
                    const std::string& path) {
  auto m = r.mapping(n, path, {"shape", "b", "h", "t", "radius", "area", "second_moment", "second_moment_out",
                               "torsion_constant"});
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
    forbid({"t", "radius", "area", "second_moment", "second_moment_out", "torsion_constant"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
  } else if (kind == "rectangular_tube") {
    s.shape = SectionShape::RectangularTube;
    forbid({"radius", "area", "second_moment", "second_moment_out", "torsion_constant"});
    s.b = r.positive(need("b"), path + ".b", " m");
    s.h = r.positive(need("h"), path + ".h", " m");
    s.t = r.positive(need("t"), path + ".t", " m");
    if (2 * s.t >= std::min(s.b, s.h))
      r.fail(need("t").Mark(), path + ".t must be < min(b, h)/2 m so the tube has a hole (got " +
                                   need("t").Scalar() + ")");
  } else if (kind == "round_rod") {
    s.shape = SectionShape::RoundRod;
    forbid({"b", "h", "t", "area", "second_moment", "second_moment_out", "torsion_constant"});
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
  } else {
    r.fail(shape.Mark(), path + ".shape: unknown shape '" + kind +
                             "' (known: rectangle, rectangular_tube, round_rod, explicit)");
  }
  return s;
}

Material readMaterial(const YamlReader& r, const std::string& name, const YAML::Node& node, const std::string& path) {
  auto mm = r.mapping(node, path, {"density", "youngs_modulus", "shear_modulus", "poisson_ratio"});
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
  return mat;
}

}  // namespace mmv::scene_detail

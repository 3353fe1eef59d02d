// A HAM-SAS isolator scene (top-level `hamsas:`).
#include "sim/scene/reader_util.hpp"

namespace mmv::scene_detail {

HamsasScene readHamsasScene(const YamlReader& r, const YAML::Node& root, const std::string& source) {
  auto top = r.mapping(root, "", {"name", "hamsas", "ground_motion", "simulation"});
  HamsasScene scene;
  scene.source = source;
  scene.name = top.count("name") ? r.text(top.at("name"), "name") : std::string("unnamed");
  HamsasSpec h;
  std::vector<std::string> allowed{"spherical_joints"};
  for (const HamsasParameter& p : hamsasParameters()) allowed.push_back(p.key);
  const YAML::Node& node = top.at("hamsas");
  auto m = r.mapping(node, "hamsas", allowed);
  for (const HamsasParameter& p : hamsasParameters()) {
    auto it = m.find(p.key);
    if (it == m.end()) continue;
    const std::string path = std::string("hamsas.") + p.key;
    h.*p.field = p.sign == HamsasParameter::Positive      ? r.positive(it->second, path, p.unit)
                 : p.sign == HamsasParameter::NonNegative ? r.nonNegative(it->second, path, p.unit)
                                                          : r.number(it->second, path);
  }
  if (m.count("spherical_joints")) {
    const std::string j = r.text(m.at("spherical_joints"), "hamsas.spherical_joints");
    if (j != "stiff" && j != "ideal")
      r.fail(m.at("spherical_joints").Mark(), "hamsas.spherical_joints must be stiff or ideal (got " + j + ")");
    h.ideal_joints = j == "ideal";
  }
  if (h.lp_length >= h.ip_length) {
    std::ostringstream os;
    os << "hamsas.lp_length must be shorter than hamsas.ip_length = " << h.ip_length << " m (got " << h.lp_length << ")";
    r.fail((m.count("lp_length") ? m.at("lp_length") : node).Mark(), os.str());
  }
  scene.isolator = h;
  if (top.count("ground_motion")) {
    const YAML::Node& g = top.at("ground_motion");
    scene.ground_motion = readTableMotion(r, g, "ground_motion", {"axis"});
    if (g["axis"]) {
      const std::string a = r.text(g["axis"], "ground_motion.axis");
      if (a != "x" && a != "y" && a != "z") r.fail(g["axis"].Mark(), "ground_motion.axis must be x, y or z (got " + a + ")");
      scene.ground_axis = a == "x" ? 0 : a == "y" ? 1 : 2;
    }
  }
  if (top.count("simulation")) scene.simulation = readSimulation(r, top.at("simulation"), false);
  return scene;
}

}  // namespace mmv::scene_detail

#include "sim/scene/reader_util.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::scene_detail {

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string readPoint(const YamlReader& r, const YAML::Node& n, const std::string& path, const ArticleSpec& a) {
  const std::string name = r.text(n, path);
  const auto names = articlePointNames(a);
  if (std::find(names.begin(), names.end(), name) == names.end())
    r.fail(n.Mark(), path + ": unknown point '" + name +
                          "' (points are <joint>, <link>.root, <link>.tip and <link>.h1 .. <link>.h<segments>)");
  return name;
}

std::string readPointOrStation(const YamlReader& r, const YAML::Node& n, const std::string& path, const ArticleSpec& a) {
  const std::string name = r.text(n, path);
  if (!isStationName(name)) return readPoint(r, n, path, a);
  std::string error;
  if (!parseStation(name, a, error)) r.fail(n.Mark(), path + ": " + error);
  return name;
}

/// Every key of a name->item mapping is allowed; duplicates are still caught.
std::vector<std::string> namesOf(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n.IsMap()) r.fail(n.Mark(), path + " must be a mapping of names (got " + YamlReader::show(n) + ")");
  std::vector<std::string> keys;
  for (auto it = n.begin(); it != n.end(); ++it)
    if (it->first.IsScalar()) keys.push_back(it->first.Scalar());
  if (keys.empty()) r.fail(n.Mark(), path + " must name at least one entry");
  return keys;
}

}  // namespace mmv::scene_detail

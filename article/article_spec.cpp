#include "article/article_spec.hpp"

namespace mmv {
namespace {
template <class T>
const T* findByName(const std::vector<T>& items, const std::string& name) {
  for (const auto& item : items)
    if (item.name == name) return &item;
  return nullptr;
}
}  // namespace

const Material* ArticleSpec::findMaterial(const std::string& n) const { return findByName(materials, n); }
const Section* ArticleSpec::findSection(const std::string& n) const { return findByName(sections, n); }
const JointSpec* ArticleSpec::findJoint(const std::string& n) const { return findByName(joints, n); }
const LinkSpec* ArticleSpec::findLink(const std::string& n) const { return findByName(links, n); }

double ArticleSpec::torqueCapacity(const std::string& c) const {
  if (const JointSpec* j = findJoint(c)) return j->torque_capacity;
  if (!base.gimbal) return 0.0;
  if (c == "gimbal.yaw") return base.gimbal->yaw.torque_capacity;
  if (c == "gimbal.pitch") return base.gimbal->pitch.torque_capacity;
  if (c == "gimbal.roll") return base.gimbal->roll.torque_capacity;
  return 0.0;
}

std::vector<std::string> articlePointNames(const ArticleSpec& a) {
  std::vector<std::string> names;
  for (const auto& j : a.joints) names.push_back(j.name);
  for (const auto& l : a.links) {
    names.push_back(l.name + ".root");
    if (!l.rigid)
      for (int k = 1; k <= l.segments; ++k) names.push_back(l.name + ".h" + std::to_string(k));
    names.push_back(l.name + ".tip");
  }
  return names;
}

}  // namespace mmv

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

}  // namespace mmv

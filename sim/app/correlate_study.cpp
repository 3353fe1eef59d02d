#include "sim/app/correlate_study.hpp"


#include <algorithm>
#include <stdexcept>

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/uff_read.hpp"

namespace mmv::app {
namespace {

MeasuredSet readMeasured(const std::string& path) {
  std::string text, why;
  if (!readInputFile(path, limits::kMaxMeasuredBytes, text, why)) throw SceneFileError(path + ": " + why);
  const uff::File file = uff::read(text, path);
  if (file.nodes.size() > static_cast<std::size_t>(limits::kMaxMeasuredNodes))
    throw SceneError(strf("%s: %zu nodes, more than the %d a correlation pairs with the article", path.c_str(),
                          file.nodes.size(), limits::kMaxMeasuredNodes));
  return measuredSet(file, path);
}

std::pair<int, std::string> namedPair(const std::string& p, Front front) {
  const auto eq = p.find('=');
  const auto bad = [&] {
    return UsageError(optionName(front, "--pair") + " " + p +
                      ": expected NODE=POINT (a node label of the file, a point or station of the scene)");
  };
  if (eq == std::string::npos || eq == 0 || eq + 1 >= p.size()) throw bad();
  int node = 0;
  try {
    std::size_t used = 0;
    node = std::stoi(p.substr(0, eq), &used);
    if (used != eq) throw bad();
  } catch (const std::logic_error&) {  // std::invalid_argument, std::out_of_range
    throw bad();
  }
  return {node, p.substr(eq + 1)};
}

CorrelateOptions options(const CorrelateRequest& r, const ArticleScene& scene) {
  checkRange(r.front, "--pair-distance", r.pair_distance_m, 1e-6, 100);
  checkRange(r.front, "--modes", r.modes, 1, 500);
  checkRange(r.front, "--mac-threshold", r.mac_threshold, 0, 1);
  checkRange(r.front, "--max-frequency-error", r.max_frequency_error, 1e-6, 100);
  if (r.damping_ratio) checkRange(r.front, "--damping", *r.damping_ratio, 0, 1);
  if (r.measured.empty()) throw UsageError(optionName(r.front, "--measured") + ": the measured UFF file is required");
  CorrelateOptions o;
  o.pair_distance_m = r.pair_distance_m;
  o.model_modes = r.modes;
  o.mac_threshold = r.mac_threshold;
  o.max_frequency_error = r.max_frequency_error;
  o.damping.modal_ratio = r.damping_ratio.value_or(0.01);
  if (scene.damping && !r.damping_ratio) o.damping = *scene.damping;
  for (const auto& p : r.pairs) {
    o.named_pairs.push_back(namedPair(p, r.front));
    checkedPoints({o.named_pairs.back().second}, scene.article, optionName(r.front, "--pair") + " " + p);
  }
  return o;
}

}  // namespace

CorrelateStudy runCorrelateStudy(const Scene& scene, const CorrelateRequest& r) {
  const ArticleScene& article = articleOf(scene, "correlate");
  const CorrelateOptions o = options(r, article);  // the options' errors before the file is read
  const MeasuredSet test = readMeasured(r.measured);
  for (const auto& [node, point] : o.named_pairs)  // the file's nodes, before any model is built
    if (std::none_of(test.nodes.begin(), test.nodes.end(), [node = node](const MeasuredNode& n) { return n.label == node; }))
      throw SceneError(strf("%s: %s %d=%s: the file defines no node %d", test.source.c_str(),
                            optionName(r.front, "--pair").c_str(), node, point.c_str(), node));
  CorrelateStudy s{correlate(article, test, o), {}, {}, {}};
  s.json = correlationJson(article, s.result);
  s.text = correlationText(article, s.result);
  s.mac_csv = macCsv(s.result);
  s.pairs_csv = correlationPairsCsv(s.result);
  checkResultFinite(s.json);
  checkResultFinite(s.text);
  return s;
}

}  // namespace mmv::app

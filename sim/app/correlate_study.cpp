#include "sim/app/correlate_study.hpp"


#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/io/correlation_report.hpp"
#include "sim/io/mat_file.hpp"
#include "sim/modes/tam.hpp"
#include "sim/io/uff_read.hpp"

namespace mmv::app {
namespace {

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

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "none" : out;
}

/// --tam FILE[:METHOD]: the TAM's mass over its channels, their nodes and directions.
TamChannels readTam(const std::string& spec, Front front) {
  const std::string opt = optionName(front, "--tam");
  std::string path = spec, method;
  const auto colon = spec.rfind(':');
  TamMethod parsed;
  if (colon != std::string::npos && parseTamMethod(spec.substr(colon + 1), parsed)) path = spec.substr(0, colon), method = tamMethodName(parsed);
  const MatContents c = readMat(path, limits::kMaxTamBytes);
  auto matrix = [&](const std::string& name) -> const Eigen::MatrixXd& {
    for (const auto& [n, m] : c.matrices)
      if (n == name) return m;
    throw SceneError(path + ": no " + name + ": not a TAM file of place-sensors --tam --out (tam.mat)");
  };
  auto strings = [&](const std::string& name) -> const std::vector<std::string>& {
    for (const auto& [n, v] : c.strings)
      if (n == name) return v;
    throw SceneError(path + ": no " + name + ": not a TAM file of place-sensors --tam --out (tam.mat)");
  };
  const std::vector<std::string>& methods = strings("Method");
  if (method.empty() && methods.size() != 1)
    throw UsageError(opt + " " + spec + ": the file holds " + std::to_string(methods.size()) + " TAMs (" + joinNames(methods) +
                     "): name one, e.g. " + path + ":" + (methods.empty() ? "guyan" : methods.front()));
  if (method.empty()) method = methods.front();
  if (std::find(methods.begin(), methods.end(), method) == methods.end())
    throw UsageError(opt + " " + spec + ": the file holds no " + method + " TAM (it holds " + joinNames(methods) + ")");
  TamChannels t;
  t.source = path, t.method = method, t.M = matrix("M_" + method), t.names = strings("Channel");
  const Eigen::MatrixXd& nodes = matrix("ChannelNode");
  const Eigen::MatrixXd& dirs = matrix("ChannelDirection");
  const Eigen::Index a = t.M.rows();
  if (t.M.cols() != a || nodes.rows() != a || nodes.cols() != 1 || dirs.rows() != a || dirs.cols() != 3 ||
      t.names.size() != static_cast<std::size_t>(a))
    throw SceneError(strf("%s: M_%s is %ldx%ld, ChannelNode %ldx%ld, ChannelDirection %ldx%ld, Channel %zu: not one TAM's channels",
                          path.c_str(), method.c_str(), static_cast<long>(t.M.rows()), static_cast<long>(t.M.cols()),
                          static_cast<long>(nodes.rows()), static_cast<long>(nodes.cols()), static_cast<long>(dirs.rows()),
                          static_cast<long>(dirs.cols()), t.names.size()));
  for (Eigen::Index i = 0; i < a; ++i) {
    t.nodes.push_back(static_cast<int>(std::lround(nodes(i, 0))));
    t.directions.push_back({dirs(i, 0), dirs(i, 1), dirs(i, 2)});
  }
  return t;
}

}  // namespace

MeasuredSet readMeasuredFile(const std::string& path) {
  std::string text, why;
  if (!readInputFile(path, limits::kMaxMeasuredBytes, text, why)) throw SceneFileError(path + ": " + why);
  const uff::File file = uff::read(text, path);
  if (file.nodes.size() > static_cast<std::size_t>(limits::kMaxMeasuredNodes))
    throw SceneError(strf("%s: %zu nodes, more than the %d a correlation pairs with the article", path.c_str(),
                          file.nodes.size(), limits::kMaxMeasuredNodes));
  return measuredSet(file, path);
}

CorrelateOptions correlateOptions(const CorrelateRequest& r, const ArticleScene& scene) {
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

void checkNamedPairNodes(const MeasuredSet& test, const CorrelateOptions& o, Front front) {
  for (const auto& [node, point] : o.named_pairs)
    if (std::none_of(test.nodes.begin(), test.nodes.end(), [node = node](const MeasuredNode& n) { return n.label == node; }))
      throw SceneError(strf("%s: %s %d=%s: the file defines no node %d", test.source.c_str(),
                            optionName(front, "--pair").c_str(), node, point.c_str(), node));
}

CorrelateStudy runCorrelateStudy(const Scene& scene, const CorrelateRequest& r) {
  const ArticleScene& article = articleOf(scene, "correlate");
  const CorrelateOptions o = correlateOptions(r, article);  // the options' errors before the file is read
  const MeasuredSet test = readMeasuredFile(r.measured);
  const std::optional<TamChannels> tam = r.tam.empty() ? std::nullopt : std::optional<TamChannels>(readTam(r.tam, r.front));
  checkNamedPairNodes(test, o, r.front);  // the file's nodes, before any model is built
  CorrelateStudy s{correlate(article, test, o), {}, {}, {}, {}, {}};
  s.json = correlationJson(article, s.result);
  s.text = correlationText(article, s.result);
  if (tam) {
    s.test_orthogonality = testOrthogonality(test, *tam);
    s.json["test_orthogonality"] = testOrthogonalityJson(*s.test_orthogonality);
    s.text += testOrthogonalityText(*s.test_orthogonality);
  }
  s.mac_csv = macCsv(s.result);
  s.pairs_csv = correlationPairsCsv(s.result);
  checkResultFinite(s.json);
  checkResultFinite(s.text);
  return s;
}

}  // namespace mmv::app

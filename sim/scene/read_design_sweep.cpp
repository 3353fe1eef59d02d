// The sweep spec (sim/scene/design_sweep_spec.hpp): read and checked key by key, then expanded
// into its points.
#include <filesystem>
#include <fstream>
#include <random>

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"
#include "sim/core/integrators.hpp"
#include "sim/scene/reader_util.hpp"
#include "sim/scene/design_sweep_spec.hpp"

namespace mmv {

using scene_detail::YamlReader;

std::vector<double> SweepParameter::gridValues() const {
  if (!is_range) return values;
  std::vector<double> v(samples);
  for (int i = 0; i < samples; ++i) {
    const double s = static_cast<double>(i) / (samples - 1);
    // Rounded to 12 digits: 0.0025, not 0.0025000000000000001, in the table and the --set.
    v[i] = std::strtod(strf("%.12g", log ? from * std::pow(to / from, s) : from + (to - from) * s).c_str(), nullptr);
  }
  v.front() = from;
  v.back() = to;
  return v;
}

double SweepParameter::at(double u) const {
  if (!is_range) return values[std::min(values.size() - 1, static_cast<std::size_t>(u * values.size()))];
  return log ? from * std::pow(to / from, u) : from + (to - from) * u;
}

namespace {

const std::vector<std::string> kOutputs{"frequencies", "mass", "deflection", "check"};

SweepParameter readParameter(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  auto m = r.mapping(n, path, {"key", "range", "values"});
  SweepParameter p;
  p.where = r.position(n.Mark());
  p.key = r.text(r.require(m, n, path, "key"), path + ".key");
  if (p.key.find('=') != std::string::npos) r.fail(m.at("key").Mark(), path + ".key names a scene key, without '=' (got " + p.key + ")");
  if (m.count("range") == m.count("values"))
    r.fail(n.Mark(), path + " needs exactly one of 'range' ({from, to, samples}) or 'values' (a list)");
  if (m.count("values")) {
    const YAML::Node& v = m.at("values");
    r.sequence(v, path + ".values");
    for (std::size_t i = 0; i < v.size(); ++i) p.values.push_back(r.number(v[i], path + strf(".values[%zu]", i)));
    return p;
  }
  const YAML::Node& rn = m.at("range");
  auto rm = r.mapping(rn, path + ".range", {"from", "to", "samples", "log"});
  p.is_range = true;
  p.from = r.number(r.require(rm, rn, path + ".range", "from"), path + ".range.from");
  p.to = r.number(r.require(rm, rn, path + ".range", "to"), path + ".range.to");
  p.samples = r.integer(r.require(rm, rn, path + ".range", "samples"), path + ".range.samples");
  if (p.from > p.to) r.fail(rm.at("to").Mark(), path + strf(".range: from %g is above to %g", p.from, p.to));
  if (p.from == p.to) r.fail(rm.at("to").Mark(), path + strf(".range is empty (from = to = %g): use values: [%g]", p.from, p.from));
  if (p.samples < 2) r.fail(rm.at("samples").Mark(), path + strf(".range.samples must be >= 2 (got %d)", p.samples));
  if (rm.count("log")) {
    const std::string l = r.text(rm.at("log"), path + ".range.log");
    if (l != "true" && l != "false") r.fail(rm.at("log").Mark(), path + ".range.log must be true or false (got " + l + ")");
    p.log = l == "true";
    if (p.log && !(p.from > 0)) r.fail(rm.at("from").Mark(), path + ".range: a log range needs from > 0");
  }
  return p;
}

void readDesign(const YamlReader& r, const YAML::Node& n, DesignSweepSpec& s) {
  if (n.IsScalar()) {
    if (n.Scalar() != "grid") r.fail(n.Mark(), "design: unknown design '" + n.Scalar() + "' (known: grid, {type: latin_hypercube, samples, seed})");
    return;
  }
  auto m = r.mapping(n, "design", {"type", "samples", "seed"});
  const std::string type = r.text(r.require(m, n, "design", "type"), "design.type");
  if (type == "grid") {
    if (m.count("samples") || m.count("seed")) r.fail(n.Mark(), "design: a grid takes no samples or seed");
    return;
  }
  if (type != "latin_hypercube") r.fail(m.at("type").Mark(), "design.type: unknown design '" + type + "' (known: grid, latin_hypercube)");
  s.design = DesignSweepSpec::Design::LatinHypercube;
  s.lhs_samples = r.integer(r.require(m, n, "design", "samples"), "design.samples");
  if (s.lhs_samples < 1 || s.lhs_samples > kMaxSweepPoints)
    r.fail(m.at("samples").Mark(), strf("design.samples must be 1 to %ld (got %d)", kMaxSweepPoints, s.lhs_samples));
  if (m.count("seed")) s.seed = static_cast<std::uint64_t>(r.nonNegative(m.at("seed"), "design.seed", ""));
}

void readOutputs(const YamlReader& r, const YAML::Node& n, DesignSweepSpec& s) {
  r.sequence(n, "outputs");
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string o = r.text(n[i], strf("outputs[%zu]", i));
    const bool json = o.rfind("json:modes/", 0) == 0 || o.rfind("json:check/", 0) == 0 || (o.rfind("first_mode:", 0) == 0 && o.size() > 11);
    if (!json && std::find(kOutputs.begin(), kOutputs.end(), o) == kOutputs.end())
      r.fail(n[i].Mark(), strf("outputs[%zu]: unknown output '%s' (known: %s, first_mode:LINK, json:modes/POINTER, json:check/POINTER)", i, o.c_str(),
                               scene_detail::joinNames(kOutputs).c_str()));
    if (std::find(s.outputs.begin(), s.outputs.end(), o) != s.outputs.end()) r.fail(n[i].Mark(), "outputs: '" + o + "' is listed twice");
    s.outputs.push_back(o);
    s.output_where.push_back(r.position(n[i].Mark()));
  }
}

}  // namespace

DesignSweepSpec parseSweepSpec(const std::string& text, const std::string& source, const std::string& folder) {
  YamlReader r(source);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw SceneError(source + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) + ": " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull())
    throw SceneError(source + ":1:1: the sweep spec is empty: it is a mapping (scene, parameters, design, outputs; docs/planning.md)");
  if (!root.IsMap())
    r.fail(root.Mark(), std::string("a sweep spec is a mapping (scene, parameters, design, outputs), not a ") +
                            (root.IsSequence() ? "list" : "scalar"));
  auto m = r.mapping(root, "", {"scene", "set", "segments", "parameters", "design", "outputs", "modes"});
  DesignSweepSpec s;
  s.source = source;
  s.text = text;
  s.scene_where = source;
  if (m.count("scene")) {
    s.scene_where = r.position(m.at("scene").Mark());
    const std::filesystem::path p = r.text(m.at("scene"), "scene");
    s.scene_path = (p.is_absolute() ? p : std::filesystem::path(folder) / p).lexically_normal().string();
  }
  if (m.count("set")) {
    r.sequence(m.at("set"), "set");
    for (std::size_t i = 0; i < m.at("set").size(); ++i) {
      s.sets.push_back(r.text(m.at("set")[i], strf("set[%zu]", i)));
      s.set_where.push_back(r.position(m.at("set")[i].Mark()));
    }
  }
  if (m.count("segments")) {
    s.segments = r.integer(m.at("segments"), "segments");
    if (s.segments < 1 || s.segments > limits::kMaxSegments)
      r.fail(m.at("segments").Mark(), strf("segments must be 1 to %d (got %d)", limits::kMaxSegments, s.segments));
  }
  const YAML::Node& params = r.require(m, root, "", "parameters");
  r.sequence(params, "parameters");
  for (std::size_t i = 0; i < params.size(); ++i) s.parameters.push_back(readParameter(r, params[i], strf("parameters[%zu]", i)));
  if (m.count("design")) readDesign(r, m.at("design"), s);
  readOutputs(r, r.require(m, root, "", "outputs"), s);
  if (m.count("modes")) {
    s.modes = r.integer(m.at("modes"), "modes");
    if (s.modes < 1 || s.modes > 100) r.fail(m.at("modes").Mark(), strf("modes must be 1 to 100 (got %d)", s.modes));
  }
  if (s.design == DesignSweepSpec::Design::Grid) {
    double n = 1;
    for (const auto& p : s.parameters) n *= static_cast<double>(p.gridValues().size());
    if (n > kMaxSweepPoints) r.fail(params.Mark(), strf("parameters: the grid has %.4g points, above the limit of %ld", n, kMaxSweepPoints));
  }
  return s;
}

DesignSweepSpec loadSweepSpec(const std::string& path) {
  std::string text, why;
  if (!readInputFile(path, limits::kMaxSceneBytes, text, why))
    throw SceneFileError(printable(path) + ": cannot read sweep spec: " + why);
  return parseSweepSpec(text, path, std::filesystem::path(path).parent_path().string());
}

std::vector<std::vector<double>> sweepPoints(const DesignSweepSpec& spec) {
  std::vector<std::vector<double>> out;
  const std::size_t n = spec.parameters.size();
  if (spec.design == DesignSweepSpec::Design::Grid) {
    std::vector<std::vector<double>> values;
    for (const auto& p : spec.parameters) values.push_back(p.gridValues());
    std::vector<std::size_t> index(n, 0);
    for (;;) {
      std::vector<double> point(n);
      for (std::size_t k = 0; k < n; ++k) point[k] = values[k][index[k]];
      out.push_back(point);
      std::size_t k = n;  // the last parameter fastest
      while (k > 0 && ++index[k - 1] == values[k - 1].size()) index[--k] = 0;
      if (k == 0) break;
    }
    return out;
  }
  std::mt19937_64 rng(spec.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int m = spec.lhs_samples;
  out.assign(m, std::vector<double>(n));
  for (std::size_t k = 0; k < n; ++k) {
    std::vector<int> strata(m);
    for (int i = 0; i < m; ++i) strata[i] = i;
    std::shuffle(strata.begin(), strata.end(), rng);
    for (int i = 0; i < m; ++i) out[i][k] = spec.parameters[k].at((strata[i] + unit(rng)) / m);
  }
  return out;
}

std::vector<std::string> pointOverrides(const DesignSweepSpec& spec, const std::vector<double>& point) {
  std::vector<std::string> sets;
  for (std::size_t k = 0; k < point.size(); ++k) sets.push_back(spec.parameters[k].key + "=" + shortest(point[k]));
  return sets;
}

}  // namespace mmv

// The rows of `mmvlab sweep` (sim/app/design_sweep_points.hpp).
#include "sim/app/design_sweep_points.hpp"
#include "sim/core/progress.hpp"

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/core/text.hpp"

#include <fstream>
#include <optional>
#include <sstream>

#include "sim/core/text.hpp"
#include "sim/io/check_report.hpp"
#include "sim/io/report.hpp"
#include "sim/modes/tracking.hpp"
#include "sim/plan/check.hpp"

namespace mmv {

namespace {

bool wants(const DesignSweepSpec& s, const std::string& o) { return std::find(s.outputs.begin(), s.outputs.end(), o) != s.outputs.end(); }

/// `name` is `link` or one of its branches (link3 -> link3a, link3b): a symmetric
/// pair's modes put equal strain in both branches, so either may come out on top.
bool isLinkOrBranch(const std::string& name, const std::string& link) {
  return name == link || (name.size() == link.size() + 1 && name.rfind(link, 0) == 0 && std::islower(static_cast<unsigned char>(name.back())));
}

std::string cell(double v) { return std::isfinite(v) ? shortest(v) : ""; }

/// A cell cannot hold the CSV's separators.
std::string clean(std::string s) {
  for (char& c : s)
    if (c == ',' || c == '\n' || c == '\r') c = c == ',' ? ';' : ' ';
  return s;
}

/// A reader's message about an override ("--set KEY=VALUE: what") without the
/// command-line wording, for an entry that came from the spec's file.
std::string withoutSetPrefix(const std::string& message, const std::string& set) {
  const std::string prefix = "--set " + set + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

ArticleScene sceneAt(const DesignSweepContext& c, const std::vector<std::string>& extra) {
  std::vector<std::string> sets = c.spec.sets;
  sets.insert(sets.end(), extra.begin(), extra.end());
  Scene s = parseScene(c.scene_text, c.scene_source, sets);
  auto* a = std::get_if<ArticleScene>(&s);
  if (!a) throw SceneError(c.spec.scene_where + ": scene " + c.scene_source + " is a HAM-SAS isolator; sweeps take article scenes");
  if (c.spec.segments > 0) overrideSegments(*a, c.spec.segments);
  return std::move(*a);
}

/// The stable vibration modes' shapes at the named points (2 rows per point, 3 on the
/// spatial model: ux, uy, uz), first `count`.
Eigen::MatrixXd pointShapes(const ModesReport& r, int count, std::vector<double>* hz) {
  std::vector<const ModeInfo*> modes;
  for (const auto& m : r.modes)
    if (m.stable && !m.rigid_body && static_cast<int>(modes.size()) < count) modes.push_back(&m);
  const Eigen::Index d = r.spatial ? 3 : 2;
  const Eigen::Index rows = modes.empty() ? 0 : d * static_cast<Eigen::Index>(modes.front()->shape.size());
  Eigen::MatrixXd s(rows, static_cast<Eigen::Index>(modes.size()));
  for (std::size_t k = 0; k < modes.size(); ++k) {
    for (std::size_t p = 0; p < modes[k]->shape.size(); ++p) {
      const PointMotion& u = modes[k]->shape[p];
      s(d * p, k) = u.ux;
      s(d * p + 1, k) = u.uy;
      if (d == 3) s(d * p + 2, k) = u.uz;
    }
    if (hz) hz->push_back(modes[k]->frequency_hz);
  }
  return s;
}

std::string jsonCell(const nlohmann::ordered_json& j, const std::string& pointer) {
  const nlohmann::ordered_json::json_pointer p(pointer);
  if (!j.contains(p)) return "";
  const auto& v = j.at(p);
  if (v.is_number()) return cell(v.get<double>());
  if (v.is_string()) return clean(v.get<std::string>());
  return clean(v.dump());
}

struct PointResult {
  ModesReport modes;
  CheckReport check;
};

PointResult analyse(const DesignSweepContext& c, const ArticleScene& scene) {
  PointResult r;
  ModesOptions mo;
  mo.with_shapes = true;
  r.modes = runModes(scene, mo);
  if (wants(c.spec, "check")) r.check = runCheck(scene, {}, &r.modes);
  return r;
}

void appendOutputs(const DesignSweepContext& c, const PointResult* r, std::vector<std::string>& cells) {
  const DesignSweepSpec& s = c.spec;
  std::optional<nlohmann::ordered_json> modes_json, check_json;  // written once per point, only when asked for
  for (const auto& o : s.outputs) {
    if (o == "frequencies") {
      const int k = static_cast<int>(c.reference_shapes.cols());
      std::vector<std::string> f(k), mac(k);
      if (r) {
        std::vector<double> hz;
        const Eigen::MatrixXd now = pointShapes(r->modes, s.modes + 6, &hz);
        if (now.rows() == c.reference_shapes.rows() && now.cols() > 0) {
          Eigen::MatrixXd padded = Eigen::MatrixXd::Zero(now.rows(), std::max(now.cols(), c.reference_shapes.cols()));
          padded.leftCols(now.cols()) = now;
          const ModeMatch m = matchModes(c.reference_shapes, padded);
          for (int t = 0; t < k; ++t)
            if (m.index[t] < now.cols()) f[t] = cell(hz[m.index[t]]), mac[t] = strf("%.4f", m.mac[t]);
        }
      }
      for (int t = 0; t < k; ++t) cells.push_back(f[t]), cells.push_back(mac[t]);
    } else if (o == "mass") {
      cells.push_back(r ? cell(r->modes.model.total_mass_kg) : "");
    } else if (o == "deflection") {
      double d = 0;
      if (r)
        for (const auto& p : r->modes.points) d = std::max(d, std::hypot(p.dx, p.dy));
      cells.push_back(r ? cell(d) : "");
    } else if (o == "check") {
      cells.push_back(r ? verdictName(r->check.overall) : "");
      for (const auto& id : c.check_ids) {
        const CheckLine* line = nullptr;
        if (r)
          for (const auto& l : r->check.lines)
            if (l.id == id) line = &l;
        cells.push_back(line && !line->unit.empty() ? cell(line->demand) : "");
        cells.push_back(line && line->has_capacity ? cell(line->margin_pct) : "");
      }
      int warnings = 0;
      if (r)
        for (const auto& l : r->check.lines) warnings += l.id == "plausibility.warning";
      cells.push_back(r ? std::to_string(warnings) : "");
    } else if (o.rfind("first_mode:", 0) == 0) {
      std::string f;
      if (r)
        for (const auto& m : r->modes.modes)
          if (m.stable && !m.rigid_body && isLinkOrBranch(m.dominant_link_strain, o.substr(11))) {
            f = cell(m.frequency_hz);
            break;
          }
      cells.push_back(f);
    } else if (o.rfind("json:modes/", 0) == 0) {
      if (r && !modes_json) modes_json = modesToJson(r->modes);
      cells.push_back(r ? jsonCell(*modes_json, o.substr(10)) : "");
    } else {
      if (r && !check_json) check_json = checkJson(r->check);
      cells.push_back(r ? jsonCell(*check_json, o.substr(10)) : "");
    }
  }
}

std::string fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : s) h = (h ^ ch) * 1099511628211ull;
  return strf("%016llx", static_cast<unsigned long long>(h));
}

void layOut(DesignSweepContext& c, const PointResult& nominal) {
  c.header = {"point"};
  for (const auto& p : c.spec.parameters) c.header.push_back(p.key);
  c.header.push_back("status");
  for (std::size_t i = 0; i < c.spec.outputs.size(); ++i) {
    const std::string& o = c.spec.outputs[i];
    if (o == "frequencies") {
      c.reference_shapes = pointShapes(nominal.modes, c.spec.modes, nullptr);
      for (Eigen::Index k = 1; k <= c.reference_shapes.cols(); ++k)
        c.header.push_back(strf("mode%ld_hz", static_cast<long>(k))), c.header.push_back(strf("mode%ld_mac", static_cast<long>(k)));
    } else if (o == "mass") {
      c.header.push_back("mass_kg");
    } else if (o == "deflection") {
      c.header.push_back("max_deflection_m");
    } else if (o.rfind("first_mode:", 0) == 0) {
      const std::string link = o.substr(11);
      bool known = false;
      std::string names;
      for (const auto& l : sceneAt(c, {}).article.links)
        known = known || isLinkOrBranch(l.name, link), names += (names.empty() ? "" : ", ") + l.name;
      if (!known) throw SceneError(c.spec.output_where[i] + ": output '" + o + "': no link '" + link + "' (known: " + names + ")");
      c.header.push_back("first_mode_" + link + "_hz");
    } else if (o == "check") {
      c.header.push_back("check_overall");
      for (const auto& l : nominal.check.lines)
        if (l.group != "plausibility") {
          c.check_ids.push_back(l.id);
          c.header.push_back(l.id + "_demand"), c.header.push_back(l.id + "_margin_pct");
        }
      c.header.push_back("plausibility_warnings");
    } else {
      const nlohmann::ordered_json j = o.rfind("json:modes/", 0) == 0 ? modesToJson(nominal.modes) : checkJson(nominal.check);
      try {
        if (!j.contains(nlohmann::ordered_json::json_pointer(o.substr(10))))
          throw SceneError(c.spec.output_where[i] + ": output '" + o + "': the nominal scene's JSON has no such field");
      } catch (const nlohmann::json::exception& e) {
        throw SceneError(c.spec.output_where[i] + ": output '" + o + "' is not a JSON pointer (/key/0/key): " + e.what());
      }
      c.header.push_back(o.substr(5));
    }
  }
  // Scene keys and JSON pointers as column names every CSV reader keeps (no '.', '/').
  for (auto& h : c.header) h = csvColumnName(h);
}

}  // namespace

DesignSweepContext prepareDesignSweep(const DesignSweepSpec& spec) {
  DesignSweepContext c;
  c.spec = spec;
  if (spec.scene_path.empty()) {
    c.scene_text = defaultSceneYaml();
    c.scene_source = "<default scene>";
  } else {
    std::string why;
    if (!readInputFile(spec.scene_path, limits::kMaxSceneBytes, c.scene_text, why))
      throw SceneFileError(spec.source + ": scene " + printable(spec.scene_path) + ": cannot read scene file: " + why);
    c.scene_source = spec.scene_path;
  }
  if (spec.outputs.empty()) throw SceneError(spec.source + ": outputs: name at least one");
  // The scene alone (its own errors carry its own positions; a HAM-SAS scene is named
  // at the spec's scene: key), then each set: entry in turn, then each parameter alone:
  // an error points at the spec's line that caused it.
  DesignSweepContext bare = c;
  bare.spec.sets.clear();
  (void)sceneAt(bare, {});
  for (std::size_t i = 0; i < spec.sets.size(); ++i) {
    try {
      bare.spec.sets.push_back(spec.sets[i]);
      (void)sceneAt(bare, {});
    } catch (const std::exception& e) {
      throw SceneError(spec.set_where.at(i) + ": set[" + std::to_string(i) + "] '" + spec.sets[i] + "': " + withoutSetPrefix(e.what(), spec.sets[i]));
    }
  }
  for (std::size_t k = 0; k < spec.parameters.size(); ++k) {  // each key, alone, as in a file
    const SweepParameter& p = spec.parameters[k];
    const std::string set = p.key + "=" + shortest(p.gridValues().empty() ? p.at(0) : p.gridValues().front());
    try {
      (void)sceneAt(c, {set});
    } catch (const std::exception& e) {
      throw SceneError(p.where + ": parameters[" + std::to_string(k) + "] '" + p.key + "': " + withoutSetPrefix(e.what(), set));
    }
  }
  const PointResult nominal = [&] {
    const ProgressStage stage("the nominal scene (before the points)");
    return analyse(c, sceneAt(c, {}));
  }();
  layOut(c, nominal);
  c.points = sweepPoints(spec);
  std::string id = std::string(mmvlabVersion()) + "\n" + spec.text + "\n" + c.scene_text + "\n" + std::to_string(spec.segments) + "\n";
  for (const auto& h : c.header) id += h + ",";
  c.fingerprint = fnv1a(id + std::to_string(c.points.size()));
  return c;
}

std::vector<std::string> evaluateDesignSweepPoint(const DesignSweepContext& c, long index) {
  const std::vector<double>& x = c.points.at(static_cast<std::size_t>(index));
  std::vector<std::string> cells;
  for (double v : x) cells.push_back(cell(v));
  std::string status = "ok";
  PointResult r;
  bool ok = true;
  try {
    r = analyse(c, sceneAt(c, pointOverrides(c.spec, x)));
  } catch (const SceneError& e) {
    status = "scene error: " + std::string(e.what()), ok = false;
  } catch (const NumericalError& e) {
    status = "numerical failure: " + std::string(e.what()), ok = false;
  }
  cells.push_back(clean(status));
  appendOutputs(c, ok ? &r : nullptr, cells);
  return cells;
}

}  // namespace mmv

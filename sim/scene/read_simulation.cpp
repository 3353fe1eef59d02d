// Scene sections: simulation settings, sensors, damping.
#include "sim/core/integrators.hpp"
#include "sim/scene/reader_util.hpp"
#include "sim/scene/stations.hpp"

namespace mmv::scene_detail {

SimulationSpec readSimulation(const YamlReader& r, const YAML::Node& n, bool article) {
  auto m = r.mapping(n, "simulation", {"duration", "integrator", "accuracy", "absolute_tolerance", "sample_rate_hz", "start",
                                        "score_points", "fidelity"});
  SimulationSpec s;
  s.fidelity = article ? SimulationSpec::Fidelity::Auto : SimulationSpec::Fidelity::Segments;
  if (article) s.integrator.clear();  // none named: the run chooses (sim/time/fidelity.hpp)
  if (m.count("fidelity") && !article)
    r.fail(m.at("fidelity").Mark(), "simulation.fidelity chooses how an article's links are carried; the isolator has none");
  if (m.count("fidelity")) {
    const std::string f = r.text(m.at("fidelity"), "simulation.fidelity");
    if (f != "auto" && f != "segments")
      r.fail(m.at("fidelity").Mark(), "simulation.fidelity: unknown fidelity '" + f + "' (known: auto, segments)");
    if (f == "segments") s.fidelity = SimulationSpec::Fidelity::Segments;
  }
  if (m.count("duration")) s.duration = r.positive(m.at("duration"), "simulation.duration", " s");
  if (m.count("integrator")) {
    s.integrator = r.text(m.at("integrator"), "simulation.integrator");
    if (!findIntegrator(s.integrator))
      r.fail(m.at("integrator").Mark(), "simulation.integrator: unknown integrator '" + s.integrator + "'" +
                                            integratorSuggestion(s.integrator) + " (known: " + integratorNames() + ")");
  }
  if (m.count("accuracy")) {
    s.accuracy = r.positive(m.at("accuracy"), "simulation.accuracy", "");
    if (s.accuracy >= 1)
      r.fail(m.at("accuracy").Mark(), "simulation.accuracy must be below 1 (a relative accuracy; got " + m.at("accuracy").Scalar() + ")");
  }
  if (m.count("absolute_tolerance")) {
    s.absolute_tolerance = r.positive(m.at("absolute_tolerance"), "simulation.absolute_tolerance", "");
    if (s.absolute_tolerance >= 1)
      r.fail(m.at("absolute_tolerance").Mark(), "simulation.absolute_tolerance must be below 1 (got " + m.at("absolute_tolerance").Scalar() + ")");
    if (!s.integrator.empty() && !isSundialsIntegrator(s.integrator))
      r.fail(m.at("absolute_tolerance").Mark(), "simulation.absolute_tolerance applies to the SUNDIALS integrators "
                                                 "(cvode_bdf, cvode_adams, arkode_erk, arkode_dirk, ida; got integrator " + s.integrator + ")");
  }
  if (m.count("sample_rate_hz")) s.sample_rate_hz = r.positive(m.at("sample_rate_hz"), "simulation.sample_rate_hz", " Hz");
  if (s.duration * s.sample_rate_hz > limits::kMaxSamples) {
    const YAML::Node& at = m.count("sample_rate_hz") ? m.at("sample_rate_hz") : m.at("duration");
    r.fail(at.Mark(), strf("simulation: %g s at %g Hz is %.3g samples, above the limit of %.0f (a rate or a duration in the "
                           "wrong unit?)", s.duration, s.sample_rate_hz, s.duration * s.sample_rate_hz, limits::kMaxSamples));
  }
  if (m.count("start")) {
    const std::string st = r.text(m.at("start"), "simulation.start");
    if (st != "equilibrium" && st != "rest") r.fail(m.at("start").Mark(), "simulation.start: unknown start '" + st + "' (known: equilibrium, rest)");
    s.from_equilibrium = st == "equilibrium";
  }
  if (m.count("score_points")) {
    const YAML::Node& sp = m.at("score_points");
    const std::size_t count = r.sequence(sp, "simulation.score_points");
    for (std::size_t i = 0; i < count; ++i)
      s.score_points.push_back(r.text(sp[i], "simulation.score_points[" + std::to_string(i) + "]"));
    s.score_where = r.file() + ":" + std::to_string(sp.Mark().line + 1) + ":" + std::to_string(sp.Mark().column + 1);
  }
  return s;
}

namespace {

/// span: [A, B]: a strain sensor's two stations (sim/scene/stations.hpp StrainSpan), and
/// `bending: in|out`, the bending it reads (in the plane by default).
void readStrainSpan(const YamlReader& r, const YAML::Node& sp, const YAML::Node* bending, const std::string& path,
                    const ArticleSpec& article, SensorSceneSpec& s) {
  if (!sp.IsSequence() || sp.size() != 2)
    r.fail(sp.Mark(), path + ".span must be [STATION, STATION], two stations of one link (got " + YamlReader::show(sp) + ")");
  if (bending) {
    const std::optional<bool> out = strainBendsOutOfPlane(r.text(*bending, path + ".bending"));
    if (!out) r.fail(bending->Mark(), path + ".bending: '" + r.text(*bending, path + ".bending") + "' is not in or out (the plane's bending or the bending out of it)");
    s.out_of_plane = *out;
  }
  const std::string a = r.text(sp[0], path + ".span[0]"), b = r.text(sp[1], path + ".span[1]");
  std::string why;
  const std::optional<StrainSpan> span = strainSpan(article, a, b, why, s.out_of_plane);
  if (!span) r.fail((bending && s.out_of_plane ? *bending : sp).Mark(), path + (bending && s.out_of_plane ? ".bending: " : ".span: ") + why);
  s.target = a;
  s.span_end = b;
  s.surface_m = span->surface_m;
  s.span_m = span->x_b - span->x_a;
}

}  // namespace

void readSensors(const YamlReader& r, const YAML::Node& n, ArticleScene& scene) {
  if (scene.instruments.empty()) scene.instruments = reportInstruments();
  const std::size_t count = r.sequence(n, "sensors");
  for (std::size_t i = 0; i < count; ++i) {
    const YAML::Node& sn = n[i];
    const std::string path = "sensors[" + std::to_string(i) + "]";
    auto m = r.mapping(sn, path, {"name", "type", "instrument", "joint", "point", "span", "bending", "axis", "noise_sigma", "seed"});
    SensorSceneSpec s;
    s.name = r.text(r.require(m, sn, path, "name"), path + ".name");
    if (m.count("instrument")) {
      const YAML::Node& in = m.at("instrument");
      s.instrument = r.text(in, path + ".instrument");
      r.known(in, path + ".instrument", "instrument", s.instrument, scene.instruments);
      s.type = findInstrument(scene, s.instrument)->spec.kind;
    }
    const YAML::Node& tn = m.count("instrument") && !m.count("type") ? m.at("instrument") : r.require(m, sn, path, "type");
    if (m.count("type")) {
      const std::string type = r.text(tn, path + ".type");
      if (!s.type.empty() && type != s.type)
        r.fail(tn.Mark(), path + ".type: " + type + ", but its instrument " + s.instrument + " is " + withArticle(s.type));
      s.type = type;
    }
    for (const char* key : {"span", "bending"})
      if (m.count(key) && s.type != "strain") r.fail(m.at(key).Mark(), path + "." + key + " applies only to strain sensors");
    if (s.type == "strain") {
      readStrainSpan(r, r.require(m, sn, path, "span"), m.count("bending") ? &m.at("bending") : nullptr, path, scene.article, s);
      if (m.count("point") || m.count("joint") || m.count("axis"))
        r.fail(sn.Mark(), path + ": a strain sensor reads its span (span: [STATION, STATION]), not a point, joint or axis");
    } else if (s.type == "encoder") {
      const YAML::Node& jn = r.require(m, sn, path, "joint");
      s.target = r.text(jn, path + ".joint");
      r.known(jn, path + ".joint", "joint", s.target, scene.article.joints);
      if (m.count("point") || m.count("axis")) r.fail(sn.Mark(), path + ": an encoder reads a joint, not a point or axis");
    } else if (s.type == "rate_gyro" || s.type == "accelerometer") {
      s.target = readPointOrStation(r, r.require(m, sn, path, "point"), path + ".point", scene.article);
      if (m.count("joint")) r.fail(m.at("joint").Mark(), path + ".joint applies only to encoders");
      s.axis = s.type == "rate_gyro" ? 2 : 0;
      if (m.count("axis")) {
        const std::string a = r.text(m.at("axis"), path + ".axis");
        if (a != "axial" && a != "transverse" && a != "normal")
          r.fail(m.at("axis").Mark(), path + ".axis: unknown axis '" + a + "' (known: axial, transverse, normal)");
        s.axis = a == "axial" ? 0 : a == "transverse" ? 1 : 2;
        // The planar model has no motion out of its plane: nothing to read along (or
        // about) anything but its in-plane axes.
        const bool in_plane = s.type == "rate_gyro" ? s.axis == 2 : s.axis != 2;
        if (scene.article.model != ArticleModel::Spatial && !in_plane)
          r.fail(m.at("axis").Mark(), path + ".axis: " + (s.type == "rate_gyro" ? "a rate gyro about" : "an accelerometer along") +
                                          " the " + a + " axis reads motion out of the plane: it needs model: spatial");
      }
    } else {
      r.fail(tn.Mark(), path + ".type: unknown sensor '" + s.type + "' (known: encoder, rate_gyro, accelerometer, strain)");
    }
    if (m.count("noise_sigma")) s.noise_sigma = r.nonNegative(m.at("noise_sigma"), path + ".noise_sigma", "");
    if (m.count("seed")) s.seed = static_cast<std::uint64_t>(r.integer(m.at("seed"), path + ".seed"));
    s.where = r.position(sn.Mark());
    scene.sensors.push_back(s);
  }
  weldSensorMasses(r, n, scene);
}

DampingSpec readDamping(const YamlReader& r, const YAML::Node& n) {
  auto m = r.mapping(n, "damping", {"modal_ratio", "rayleigh", "hinge_beta"});
  if (m.size() != 1) r.fail(n.Mark(), "damping must give exactly one of modal_ratio, rayleigh, hinge_beta");
  DampingSpec d;
  if (m.count("modal_ratio")) {
    d.kind = DampingSpec::Kind::Modal;
    d.modal_ratio = r.nonNegative(m.at("modal_ratio"), "damping.modal_ratio", "");
    if (d.modal_ratio >= 1) r.fail(m.at("modal_ratio").Mark(), "damping.modal_ratio must be < 1 (got " + m.at("modal_ratio").Scalar() + ")");
  } else if (m.count("rayleigh")) {
    const YAML::Node& rn = m.at("rayleigh");
    auto rm = r.mapping(rn, "damping.rayleigh", {"alpha", "beta"});
    d.kind = DampingSpec::Kind::Rayleigh;
    if (rm.count("alpha")) d.alpha = r.nonNegative(rm.at("alpha"), "damping.rayleigh.alpha", " 1/s");
    if (rm.count("beta")) d.beta = r.nonNegative(rm.at("beta"), "damping.rayleigh.beta", " s");
  } else {
    d.kind = DampingSpec::Kind::HingeViscous;
    d.hinge_beta = r.positive(m.at("hinge_beta"), "damping.hinge_beta", " s");
  }
  return d;
}

}  // namespace mmv::scene_detail

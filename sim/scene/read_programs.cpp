// Scene sections: table, ground and torque programs; torquer and gimbal slews.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include "sim/core/files.hpp"
#include "sim/core/integrators.hpp"
#include "sim/scene/programs.hpp"
#include "sim/scene/reader_util.hpp"

namespace mmv::scene_detail {

namespace {

/// The text of the file a `file:` key names (relative to the scene's folder), its path
/// in `source`; refused at the key ("cannot read <what> '<path>': why").
std::string readNamedFile(const YamlReader& r, const YAML::Node& fn, const std::string& key, const std::string& what,
                          std::string& source) {
  std::filesystem::path file = r.text(fn, key);
  if (file.is_relative()) file = std::filesystem::path(r.file()).parent_path() / file;
  std::string text, why;
  if (!readInputFile(file.string(), limits::kMaxProfileBytes, text, why))
    r.fail(fn.Mark(), key + ": cannot read " + what + " '" + file.string() + "': " + why);
  source = file.string();
  return text;
}

}  // namespace

TableMotion readTableMotion(const YamlReader& r, const YAML::Node& mn, const std::string& path,
                            const std::vector<std::string>& extra, const std::string& unit) {
  std::vector<std::string> keys{"type", "amplitude", "frequency_hz", "ramp_s", "from_hz", "to_hz", "duration", "log", "rms", "seed", "file"};
  keys.insert(keys.end(), extra.begin(), extra.end());
  auto mm = r.mapping(mn, path, keys);
  const YAML::Node& tn = r.require(mm, mn, path, "type");
  const std::string t = r.text(tn, path + ".type");
  auto need = [&](const char* k) -> const YAML::Node& { return r.require(mm, mn, path, k); };
  auto only = [&](std::initializer_list<const char*> allowed) {
    for (const auto& [k, v] : mm) {
      bool ok = k == "type" || std::find(extra.begin(), extra.end(), k) != extra.end();
      for (const char* a : allowed) ok = ok || k == a;
      if (!ok) r.fail(v.Mark(), path + "." + k + " does not apply to a " + t + " program");
    }
  };
  TableMotion tm;
  if (t == "sine") {
    only({"amplitude", "frequency_hz", "ramp_s"});
    tm.type = TableMotion::Type::Sine;
    if (mm.count("ramp_s")) tm.ramp = r.nonNegative(mm.at("ramp_s"), path + ".ramp_s", " s");
    tm.amplitude = r.number(need("amplitude"), path + ".amplitude");
    tm.frequency_hz = r.positive(need("frequency_hz"), path + ".frequency_hz", " Hz");
  } else if (t == "sweep") {
    only({"amplitude", "from_hz", "to_hz", "duration", "log"});
    tm.type = TableMotion::Type::Sweep;
    tm.amplitude = r.number(need("amplitude"), path + ".amplitude");
    tm.from_hz = r.positive(need("from_hz"), path + ".from_hz", " Hz");
    tm.to_hz = r.positive(need("to_hz"), path + ".to_hz", " Hz");
    tm.duration = r.positive(need("duration"), path + ".duration", " s");
    if (mm.count("log")) {
      const std::string l = r.text(mm.at("log"), path + ".log");
      if (l != "true" && l != "false") r.fail(mm.at("log").Mark(), path + ".log must be true or false (got " + l + ")");
      tm.logarithmic = l == "true";
    }
  } else if (t == "random") {
    only({"rms", "from_hz", "to_hz", "duration", "seed"});
    tm.type = TableMotion::Type::Random;
    tm.rms = r.nonNegative(need("rms"), path + ".rms", unit);
    tm.from_hz = r.positive(need("from_hz"), path + ".from_hz", " Hz");
    tm.to_hz = r.positive(need("to_hz"), path + ".to_hz", " Hz");
    if (tm.to_hz <= tm.from_hz) r.fail(mm.at("to_hz").Mark(), path + ".to_hz must be > from_hz (got " + mm.at("to_hz").Scalar() + ")");
    tm.duration = r.positive(need("duration"), path + ".duration", " s");
    if (mm.count("seed")) tm.seed = static_cast<std::uint64_t>(r.integer(mm.at("seed"), path + ".seed"));
  } else if (t == "csv") {
    only({"file"});
    tm.type = TableMotion::Type::Profile;
    tm.profile_csv = readNamedFile(r, need("file"), path + ".file", "profile", tm.profile_source);
  } else {
    r.fail(tn.Mark(), path + ".type: unknown program '" + t + "' (known: sine, sweep, random, csv)");
  }
  // The facility builds the program now, so a program it refuses (a CSV profile it
  // cannot read) is an error at this key, not when a model is built.
  try {
    (void)makeTableProgram(tm);
  } catch (const std::invalid_argument& e) {
    r.fail(mn.Mark(), path + ": " + e.what());
  }
  return tm;
}

SlewSpec readSlew(const YamlReader& r, const YAML::Node& sn, const std::string& path) {
  auto sm = r.mapping(sn, path, {"to_deg", "start_s", "shape", "max_rate_deg_s", "max_acceleration_deg_s2", "rate_deg_s", "ramp_s", "file"});
  SlewSpec sl;
  std::string sh = "cycloidal";
  if (sm.count("shape")) {
    sh = r.text(sm.at("shape"), path + ".shape");
    if (sh != "cycloidal" && sh != "trapezoidal" && sh != "spin_up" && sh != "program")
      r.fail(sm.at("shape").Mark(), path + ".shape: unknown shape '" + sh + "' (known: cycloidal, trapezoidal, spin_up, program)");
  }
  // Each shape's keys, and no other's.
  const std::vector<std::string> move_keys{"to_deg", "max_rate_deg_s", "max_acceleration_deg_s2"};
  const std::vector<std::string> allowed = sh == "spin_up" ? std::vector<std::string>{"rate_deg_s", "ramp_s"}
                                           : sh == "program" ? std::vector<std::string>{"file"}
                                                             : move_keys;
  for (const auto& [k, v] : sm)
    if (k != "shape" && k != "start_s" && std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      r.fail(v.Mark(), path + "." + k + " does not apply to a " + sh + " slew");
  if (sm.count("start_s")) sl.start_time = r.nonNegative(sm.at("start_s"), path + ".start_s", " s");
  if (sh == "spin_up") {
    const YAML::Node& rn = r.require(sm, sn, path, "rate_deg_s");
    sl.spin_rate = r.number(rn, path + ".rate_deg_s") * kDegToRad;
    if (sl.spin_rate == 0) r.fail(rn.Mark(), path + ".rate_deg_s must not be 0 (its sign is the direction)");
    sl.spin_ramp = r.positive(r.require(sm, sn, path, "ramp_s"), path + ".ramp_s", " s");
    return sl;
  }
  if (sh == "program") {
    const YAML::Node& fn = r.require(sm, sn, path, "file");
    sl.program_csv = readNamedFile(r, fn, path + ".file", "the angle program", sl.program_source);
    try {
      (void)facility::csvProfile(sl.program_csv, sl.program_source);
    } catch (const std::invalid_argument& e) {
      r.fail(fn.Mark(), path + ".file: " + e.what());
    }
    return sl;
  }
  sl.to = r.number(r.require(sm, sn, path, "to_deg"), path + ".to_deg") * kDegToRad;
  sl.trapezoidal = sh == "trapezoidal";
  if (sm.count("max_rate_deg_s")) sl.max_rate = r.positive(sm.at("max_rate_deg_s"), path + ".max_rate_deg_s", " deg/s") * kDegToRad;
  if (sm.count("max_acceleration_deg_s2"))
    sl.max_acceleration = r.positive(sm.at("max_acceleration_deg_s2"), path + ".max_acceleration_deg_s2", " deg/s^2") * kDegToRad;
  return sl;
}

}  // namespace mmv::scene_detail

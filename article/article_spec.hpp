#pragma once
/// Plain-data description of a planar test article: links (flexible or rigid),
/// joints with their torquers, and the base. No Simbody here; `article_builder.hpp`
/// turns this into a model.
///
/// Frames: the article moves in the world x-y plane, joints rotate about world z.
/// A link's frame has its origin at the link root (the joint) and x along the
/// undeformed link. A joint angle is the rotation (about z, counter-clockwise
/// positive) of the child link relative to the parent's tip frame, or relative to
/// the base frame for a joint on the base.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "article/section.hpp"

namespace mmv {

/// A point mass with rotary inertia about the out-of-plane axis through it.
struct LumpedMass {
  double mass = 0;            ///< kg, >= 0.
  double rotary_inertia = 0;  ///< kg*m^2 about z through the mass, >= 0.
  /// m, where the mass sits across the link's section at its point: along the in-plane
  /// normal (y) and the plane's normal (z, spatial model only); {0, 0} on the axis.
  std::array<double, 2> offset{0, 0};
};

/// How the joint's torquer holds the commanded angle during statics and modes.
enum class JointHold {
  Locked,  ///< Holds exactly (infinitely stiff servo): the joint is not a DOF.
  Free,    ///< Frictionless pin, no torque: the angle follows from equilibrium.
  Servo,   ///< A rotational spring of `servo_stiffness` pulling to the commanded angle.
};

/// A motion program of the table along world x (facility/table_programs.hpp).
struct TableMotion {
  enum class Type { Sine, Sweep, Random, Profile } type = Type::Sine;
  /// A sine dwell x = amplitude sin(2 pi f t).
  static TableMotion sine(double amplitude, double frequency_hz) {
    TableMotion m;
    m.amplitude = amplitude;
    m.frequency_hz = frequency_hz;
    return m;
  }
  double amplitude = 0;     ///< m (sine, sweep).
  double frequency_hz = 0;  ///< Hz (sine).
  double ramp = 0;          ///< s (sine): raised-cosine ramp-in; 0: none.
  double from_hz = 0, to_hz = 0;  ///< Hz (sweep, random band).
  double duration = 0;      ///< s (sweep, random).
  bool logarithmic = false; ///< sweep.
  double rms = 0;           ///< m (random).
  std::uint64_t seed = 1;   ///< random.
  std::string profile_csv;  ///< profile: the CSV text (time_s,x_m).
  std::string profile_source;  ///< profile: its file, for messages.
};

/// A commanded slew of a locked joint in time runs (facility/slews.hpp).
struct SlewSpec {
  double to = 0;             ///< rad, final angle.
  double start_time = 0;     ///< s.
  bool trapezoidal = false;  ///< else cycloidal.
  double max_rate = 70 * 3.14159265358979323846 / 180;          ///< rad/s.
  double max_acceleration = 200 * 3.14159265358979323846 / 180; ///< rad/s^2.
  /// != 0 (rad/s): a spin-up to this rate over `spin_ramp` s (facility/slews.hpp),
  /// turning on at it, instead of a move to `to`; needs a continuous joint.
  double spin_rate = 0;
  double spin_ramp = 0;        ///< s.
  std::string program_csv;     ///< non-empty: an angle program (time_s,angle_deg) instead of a move.
  std::string program_source;  ///< its file, for messages.
};

struct JointSpec {
  std::string name;
  std::string parent;      ///< "base" or the name of a link (or branch) whose tip carries it.
  double angle = 0;        ///< commanded angle in rad.
  double range = 45 * 3.14159265358979323846 / 180;  ///< rad, +-: the torquer's travel (report: +-45 deg); angles and slews within it.
  JointHold hold = JointHold::Locked;
  double servo_stiffness = 0;  ///< N*m/rad, > 0 when hold is Servo.
  std::optional<LumpedMass> torquer;  ///< lumped on the parent side (stator housing).
  std::optional<SlewSpec> slew;       ///< time runs: a locked joint follows it from `angle`.
  double torque_capacity = 0;         ///< N*m the torquer can give (0: not checked).
  /// Time runs: a commanded torque on a free or servo joint, as a program whose
  /// "displacement" is the torque in N*m (facility/table_programs.hpp).
  std::optional<TableMotion> torque_input;
  /// range_deg: unlimited (a slip ring): a slew may turn past any angle; `range` is then
  /// pi, the travel over which a holding torque is worst.
  bool continuous = false;
};

/// How the links are discretized (docs/spatial.md). Planar: bending in the plane of
/// motion only (pins about z). Spatial: every hinge also bends out of the plane and
/// twists (three body-fixed rotations: torsion about the link, out-of-plane bending
/// about the in-plane normal, in-plane bending about z), so out-of-plane and torsion
/// modes exist; with those two held it is the planar model.
enum class ArticleModel { Planar, Spatial };

struct LinkSpec {
  std::string name;
  std::string joint;       ///< the joint at the link's root.
  std::string material;    ///< name of a Material.
  std::string section;     ///< name of a Section.
  double length = 0;       ///< m, > 0.
  int segments = 1;        ///< flexible elements per link (>= 1); ignored when rigid.
  bool rigid = false;      ///< one rigid body instead of a flexible chain.
  /// Time runs: > 0 carries the link's hinges by its first `modes` modes with its root
  /// held and the rest of the article rigid (sim/time/modal_links.hpp) instead of one
  /// coordinate per hinge; 0: every hinge its own coordinate. At most its hinge count.
  int modes = 0;
  double mount_angle = 0;  ///< rad, link direction relative to the joint's rotor frame.
  /// rad, the link's tilt out of the plane of motion (toward +z) about the rotor frame's
  /// in-plane normal, after mount_angle: branches spread out of the plane (spatial model).
  double tilt = 0;
  std::optional<LumpedMass> tip_mass;  ///< rigidly attached at the tip.
  /// Point masses welded on the link's axis at distances from its root (m, kg): the
  /// sensors a placement adds (place-sensors --sensor-mass), not a scene key.
  std::vector<std::pair<double, double>> station_masses;
  std::string key;  ///< the scene entry it was read from ("links[2]"; a branch shares its link's), for messages.
  /// How this link bends (ArticleSpec::linkModel): none takes the article's model. A
  /// planar link of a spatial article bends in its plane only (pin hinges: rigid out of
  /// the plane and in torsion) while it moves in 3-D with the rest of the article.
  std::optional<ArticleModel> model;
  /// Time runs, `modes` 0: set, the link is carried by its modes up to this frequency
  /// (Hz), at least kFidelityMinModes of them (sim/time/fidelity.hpp sets it: the
  /// scene's default fidelity). Not a scene key.
  std::optional<double> modes_up_to_hz;
  /// Time runs in modal coordinates, above 1: the link also keeps its modes up to this
  /// times the highest frequency its `modes:` or the rule keep, and at least one more
  /// (capped at the hinges): a verification companion's 2 (sim/time/verify.hpp). Not a
  /// scene key.
  double modes_frequency_factor = 1;
  /// With modes_up_to_hz, a start at rest (a release): also the modes until those left
  /// out carry at most kReleaseStaticShare of the link's static response to the load it
  /// is released under (sim/time/fidelity.hpp). Not a scene key.
  bool modes_cover_release = false;
  /// Whether a time run carries the link in modal coordinates.
  bool modal() const { return !rigid && (modes > 0 || modes_up_to_hz.has_value()); }
};

/// A loop closure: a point of the article held to the ground (a fixture) or to
/// another point of the article (report figure 7, closed trees).
enum class ClosureType {
  Pin,     ///< both in-plane directions held (a planar ball joint is the same).
  Slider,  ///< held across a line, free to slide along it.
};

struct ClosureSpec {
  std::string name;
  std::string point;          ///< a named point of the article.
  std::string to = "ground";  ///< "ground" or another named point.
  ClosureType type = ClosureType::Pin;
  std::optional<std::array<double, 3>> at;  ///< m, ground anchor; default: the point in the reference shape.
  double direction = 0;       ///< rad, slider: world direction of the line it slides along.
  std::string where;          ///< "file:line:col" of its entry, for errors found later.
};

/// A constant force (dead load) at a named point, in the world frame.
struct LoadSpec {
  std::string point;
  std::array<double, 3> force{0, 0, 0};  ///< N, z = 0.
  std::string where;
};

/// BaseType::Floating (planar: rotation and both translations free) is not offered in
/// scene files; component-mode analyses use it for free-free links. BaseType::Table:
/// the base sits on the base excitation table, a body sliding along world x whose
/// motion is prescribed (held at rest in statics and modes).
enum class BaseType { Fixed, Floating, Table };

/// One axis of the gimbal (AGS, docs/sources.md section 2): an angle it holds, or a slew.
struct GimbalAxisSpec {
  double angle = 0;             ///< rad, commanded (the start of a slew).
  std::optional<SlewSpec> slew;
  double range = 0;             ///< rad: |angle| and a slew's end stay within it.
  double torque_capacity = 0;   ///< N*m the axis motor can give.
  bool continuous = false;      ///< as JointSpec::continuous (last: axes are brace-initialised).
};

/// The 3-axis gimbal between the table (or the floor) and the article's base: yaw about
/// the vertical (world y), then pitch about the normal of the article's plane (z),
/// then roll about world x, outer to inner. All three are held (statics, modes) or
/// driven (time runs) by their motors; the article's planar joints ride on the roll
/// ring (the payload plate), so pitch turns the article in its plane and yaw and roll
/// turn that plane (the links stay rigid out of it).
struct GimbalSpec {
  static constexpr double kDeg = 3.14159265358979323846 / 180;
  GimbalAxisSpec yaw{0, {}, 45 * kDeg, 200}, pitch{0, {}, 45 * kDeg, 200}, roll{0, {}, 90 * kDeg, 50};
  double ring_mass = 10;     ///< kg of each moving ring (the roll ring carries the payload plate).
  double ring_inertia = 1;   ///< kg*m^2 of each ring about every axis.
};

struct BaseSpec {
  BaseType type = BaseType::Fixed;
  std::array<double, 3> position{0, 0, 0};  ///< m, world frame.
  double direction = 0;  ///< rad, world direction of a base joint's zero angle (from +x, ccw).
  double table_mass = 100;  ///< kg, the table's moving mass (BaseType::Table).
  std::optional<TableMotion> motion;  ///< BaseType::Table: the program; none = at rest.
  /// BaseType::Table, spatial model: the program across the plane of motion (world z:
  /// the report's table y axis), on a stage riding the x table; none = no such stage.
  std::optional<TableMotion> motion_z;
  std::optional<GimbalSpec> gimbal;   ///< built only when the scene names one.
};


/// The factors of safety a stress is judged with (docs/strength.md): margin =
/// allowable / (factor * stress) - 1. The defaults are NASA-STD-5001B's for metallic
/// flight hardware tested as protoflight (yield 1.25, ultimate 1.4; docs/sources.md
/// section 7); the scene's `strength:` states the lab's own.
struct StrengthFactors {
  double yield_factor = 1.25;
  double ultimate_factor = 1.4;
  bool given = false;  ///< the scene stated them (else the defaults above).
};

struct ArticleSpec {
  ArticleModel model = ArticleModel::Planar;
  /// Spatial model only, for checks (not a scene key): the out-of-plane and torsion
  /// coordinates of every hinge are held, leaving the planar model's motions.
  bool lock_out_of_plane = false;
  std::vector<Material> materials;
  std::vector<Section> sections;
  std::vector<JointSpec> joints;
  std::vector<LinkSpec> links;  ///< branches already expanded into separate links.
  std::vector<ClosureSpec> closures;
  std::vector<LoadSpec> loads;
  BaseSpec base;
  StrengthFactors strength;

  const Material* findMaterial(const std::string& name) const;
  const Section* findSection(const std::string& name) const;
  const JointSpec* findJoint(const std::string& name) const;
  const LinkSpec* findLink(const std::string& name) const;
  /// How link `l` bends: its own model, else the article's. A spatial link needs a
  /// spatial article (the scene reader makes the article spatial when a link is).
  ArticleModel linkModel(const LinkSpec& l) const { return l.model.value_or(model); }
  bool bendsOutOfPlane(const LinkSpec& l) const {
    return model == ArticleModel::Spatial && linkModel(l) == ArticleModel::Spatial;
  }
  /// The torque capacity (N*m, 0: not given) of a joint's torquer or of a gimbal axis
  /// ("gimbal.yaw", "gimbal.pitch", "gimbal.roll").
  double torqueCapacity(const std::string& coordinate) const;
};

/// The named points the builder creates for `a` (see article_builder.hpp), in order.
std::vector<std::string> articlePointNames(const ArticleSpec& a);

}  // namespace mmv

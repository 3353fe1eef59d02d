#include "sim/model/article_builder.hpp"

#include <algorithm>

#include "sim/core/errors.hpp"
#include "sim/model/attachments.hpp"
#include "sim/model/motions.hpp"
#include <limits>
#include <cmath>
#include <deque>
#include <map>

#include "article/flexible_link.hpp"
#include "facility/slews.hpp"

namespace mmv {
namespace {

SimTK::Transform rotZ(double angle, const SimTK::Vec3& p = SimTK::Vec3(0)) {
  return SimTK::Transform(SimTK::Rotation(angle, SimTK::ZAxis), p);
}

/// A rigid body of mass m whose mass centre is at `com` in its frame, with inertia
/// `central` about that centre. Simbody stores the inertia about the frame origin and
/// subtracts the shift again when it builds the tree, refusing a moment below -1.8e-14:
/// a lumped mass without rotary inertia (58.94 kg, 2 m off its link) came back as
/// -2.8e-14 and ended the run (exit 70). Each central moment is at least 1e-12 m |com|^2,
/// far above that round-off and far below anything the dynamics can see.
SimTK::Body::Rigid rigidBody(double m, const SimTK::Vec3& com, const SimTK::Inertia& central) {
  const double floor = 1e-12 * m * com.normSqr();
  SimTK::Mat33 I = central.toMat33();
  for (int i = 0; i < 3; ++i) I(i, i) = std::max(I(i, i), floor);
  const SimTK::Inertia c(SimTK::SymMat33(I(0, 0), I(1, 0), I(1, 1), I(2, 0), I(2, 1), I(2, 2)));
  return SimTK::Body::Rigid(SimTK::MassProperties(m, com, c.shiftFromMassCenter(-com, m)));
}

/// A piece of length l and mass m, origin at its inboard end, x along the piece.
/// In the plane only Izz = m l^2 / 12 about the centre matters (Euler-Bernoulli: no
/// section rotary inertia). The out-of-plane axes get the section's gyration r^2 = I/A,
/// Ixx = m r^2 and Iyy = m (l^2/12 + r^2), which keeps the inertia physically valid
/// (triangle inequality) for short, thick pieces.
SimTK::Body::Rigid pieceBody(const LinkPiece& p, double gyration_sq) {
  const SimTK::Vec3 com(0.5 * p.length, 0, 0);
  const SimTK::Inertia central(p.mass * gyration_sq, p.inertia_zz_about_com + p.mass * gyration_sq,
                               p.inertia_zz_about_com);
  return rigidBody(p.mass, com, central);
}

/// The spatial model's piece: the same in-plane inertia (Euler-Bernoulli: m l^2/12 about
/// z), the same about the in-plane normal y (so a round rod's two bending families pair
/// exactly), and the section's polar inertia about the link axis, m (I + I_out) / A,
/// which torsion needs. A piece shorter than sqrt(6 (I + I_out) / A) would break the
/// triangle inequality of a rigid body's moments: the bending moments then get the least
/// share s of the section's own rotary inertia that restores it, m I/A s about z and
/// m I_out/A s about y, s = 1 - 2 (m l^2/12) / (m (I + I_out)/A) (none on the default
/// article below 18 segments per link, docs/spatial.md). As the pieces shrink s goes to
/// 1: each slice carries its true rotary inertia (a Rayleigh beam), whatever the section.
/// (Before, both axes got the same m (I + I_out)/(2A) s: 8.5 times the true in-plane
/// rotary inertia of a 20 x 5 mm strip, which pulled its in-plane modes below the beam's
/// as the mesh was refined. For a round rod the two are the same.) A section that states
/// no I_out (`out_of_plane` as `in_plane`): `in_share` 0.5, both axes alike.
SimTK::Body::Rigid spatialPieceBody(const LinkPiece& p, double polar_gyration_sq, double in_share) {
  const SimTK::Vec3 com(0.5 * p.length, 0, 0);
  const double bend = p.inertia_zz_about_com, polar = p.mass * polar_gyration_sq;
  const double s = polar > 0 ? std::max(0.0, 1.0 - 2 * bend / polar) : 0.0;
  const SimTK::Inertia central(polar, bend + s * polar * (1 - in_share), bend + s * polar * in_share);
  return rigidBody(p.mass, com, central);
}

/// X_BM of a link's root piece on its joint: the link turned by its mount angle about z,
/// then tilted out of the plane (toward +z) about y by its tilt.
SimTK::Transform mountFrame(const LinkSpec& l) {
  if (l.tilt == 0) return rotZ(-l.mount_angle);
  return SimTK::Transform(SimTK::Rotation(l.tilt, SimTK::YAxis) * SimTK::Rotation(-l.mount_angle, SimTK::ZAxis));
}

/// A lumped mass at the body origin with rotary inertia J about z (disc-like: J/2 in x, y).
SimTK::Body::Rigid lumpedBody(const LumpedMass& m) {
  const double j = m.rotary_inertia;
  const SimTK::Vec3 c(0, m.offset[0], m.offset[1]);  // across the section, in the link's tip frame
  const SimTK::Inertia about_c(0.5 * j, 0.5 * j, j);  // a disk about the plane's normal
  return rigidBody(m.mass, c, about_c);
}

struct Frame {  // a place to attach things: a body and a frame on it
  SimTK::MobilizedBodyIndex mobod;
  SimTK::Transform X_BF;
  bool grounded = false;
};

class Builder {
 public:
  Builder(const ArticleScene& scene, Model& model) : scene_(scene), a_(scene.article), model_(model) {}

  void build() {
    auto& matter = model_.updMatter();
    const BaseSpec& base = a_.base;
    const SimTK::Vec3 p_base(base.position[0], base.position[1], base.position[2]);
    Frame ground{matter.Ground().getMobilizedBodyIndex(), rotZ(base.direction, p_base), true};
    if (base.type == BaseType::Table) {
      // The table slides along world x; the article's base joints sit on it.
      const int part = model_.addPart("table", Part::Kind::Table, "");
      SimTK::MobilizedBody::Slider table(matter.updGround(), SimTK::Transform(p_base),
                                         SimTK::Body::Rigid(SimTK::MassProperties(base.table_mass, SimTK::Vec3(0),
                                                                                  SimTK::Inertia(base.table_mass))),
                                         SimTK::Transform());
      Coordinate c = sliderCoordinate("table.x", "table", table.getMobilizedBodyIndex());
      c.held = true;  // at rest in statics and modes; driven in time runs
      model_.addCoordinate(c);
      model_.addBody(table.getMobilizedBodyIndex(), part, true);
      if (base.motion) model_.setPrescribedMotion(c.mobod, prescribeTableProgram(table, makeTableProgram(*base.motion)));
      // Held in statics and modes, so what is welded to it counts as fixed there.
      ground = Frame{table.getMobilizedBodyIndex(), rotZ(base.direction), true};
      if (base.motion_z) ground = buildTableZStage(*base.motion_z, table.getMobilizedBodyIndex(), part, ground);
    }
    if (base.gimbal) ground = buildGimbal(*base.gimbal, ground);
    // Breadth-first from the base so that every parent exists before its children.
    std::deque<std::pair<const JointSpec*, Frame>> todo;
    for (const auto& j : a_.joints)
      if (j.parent == "base") todo.push_back({&j, ground});
    while (!todo.empty()) {
      auto [joint, parent] = todo.front();
      todo.pop_front();
      buildJoint(*joint, parent);
      for (const auto& j : a_.joints) {
        auto it = tips_.find(j.parent);
        if (it != tips_.end() && !built_joints_.count(j.name) && !queued_.count(j.name)) {
          queued_.insert({j.name, true});
          todo.push_back({&j, it->second});
        }
      }
    }
  }

 private:
  /// Holds a locked pin at its angle or drives it along its slew from there (the reader
  /// held the slew to the range; check's holding grid moves its start).
  void holdOrSlew(SimTK::MobilizedBody& pin, double angle, const std::optional<SlewSpec>& spec, bool continuous) {
    if (spec) {
      model_.setPrescribedMotion(pin.getMobilizedBodyIndex(),
                                       prescribeSlew(pin, makeSlew(*spec, angle, INFINITY, continuous), spec->start_time));
    } else {
      model_.setPrescribedMotion(pin.getMobilizedBodyIndex(), prescribeRest(pin));
    }
  }

  /// Yaw (about y), pitch (about z), roll (about x), outer to inner, on `parent` without
  /// its base-direction rotation; returns the frame on the roll ring where the base
  /// joints go. Each ring is a held coordinate "gimbal.<axis>".
  Frame buildGimbal(const GimbalSpec& g, const Frame& parent) {
    auto& matter = model_.updMatter();
    const int part = model_.addPart("gimbal", Part::Kind::Gimbal, "");
    const SimTK::Body::Rigid ring(SimTK::MassProperties(g.ring_mass, SimTK::Vec3(0), SimTK::Inertia(g.ring_inertia)));
    // A pin turns about its frames' z; these rotations put z along the axis.
    const SimTK::Rotation z_to_y(-M_PI / 2, SimTK::XAxis), z_to_x(M_PI / 2, SimTK::YAxis);
    const struct {
      const char* name;
      const GimbalAxisSpec* spec;
      SimTK::Rotation axis;
    } axes[3] = {{"gimbal.yaw", &g.yaw, z_to_y}, {"gimbal.pitch", &g.pitch, SimTK::Rotation()}, {"gimbal.roll", &g.roll, z_to_x}};
    SimTK::MobilizedBodyIndex inboard = parent.mobod;
    SimTK::Transform X_inboard(parent.X_BF.p());  // the parent frame's origin, world-aligned
    for (const auto& a : axes) {
      SimTK::MobilizedBody::Pin pin(matter.updMobilizedBody(inboard), SimTK::Transform(a.axis, X_inboard.p()), ring,
                                    SimTK::Transform(a.axis));
      Coordinate c;
      c.name = a.name;
      c.kind = CoordinateKind::Joint;
      c.motion = CoordinateMotion::Rotation;
      c.part = "gimbal";
      c.mobod = pin.getMobilizedBodyIndex();
      c.reference = a.spec->angle;
      c.held = true;
      model_.addCoordinate(c);
      model_.addBody(pin.getMobilizedBodyIndex(), part, parent.grounded);
      holdOrSlew(pin, a.spec->angle, a.spec->slew, a.spec->continuous);
      inboard = pin.getMobilizedBodyIndex();
      X_inboard = SimTK::Transform();
    }
    return Frame{inboard, rotZ(a_.base.direction), parent.grounded};
  }

  void buildJoint(const JointSpec& j, const Frame& parent) {
    built_joints_[j.name] = true;
    auto& matter = model_.updMatter();
    model_.addPoint({j.name, parent.mobod, parent.X_BF.p(), true});
    if (j.torquer) {
      const int part = model_.addPart(j.name + ".torquer", Part::Kind::Torquer, j.parent == "base" ? "" : j.parent);
      SimTK::MobilizedBody::Weld w(matter.updMobilizedBody(parent.mobod), parent.X_BF, lumpedBody(*j.torquer),
                                   SimTK::Transform());
      model_.addBody(w.getMobilizedBodyIndex(), part, parent.grounded);
    }
    std::vector<const LinkSpec*> children;
    for (const auto& l : a_.links)
      if (l.joint == j.name) children.push_back(&l);
    MMV_DEMAND(!children.empty());
    // The first child's root piece carries the pin; the others are welded to it.
    Rotor rotor;
    for (std::size_t c = 0; c < children.size(); ++c) buildLink(j, *children[c], c == 0, parent, rotor);
  }

  /// The body that turns with a joint, and the mount angle of the link it belongs to.
  struct Rotor {
    SimTK::MobilizedBodyIndex mobod;
    SimTK::Transform mount;  ///< X_BM of the rotor's link (mountFrame): its joint frame on it.
  };

  /// One link of joint j: its pieces and hinges, named points and tip mass. The first
  /// link of a joint (`first`) carries the joint's mobilizer and becomes the rotor.
  void buildLink(const JointSpec& j, const LinkSpec& l, bool first, const Frame& parent, Rotor& rotor) {
    auto& matter = model_.updMatter();
    const LinkDiscretization d = discretize(l);
    const int part = model_.addPart(l.name, Part::Kind::Link, l.name);
    const Section& section = *a_.findSection(l.section);
    const double gyr2 = sectionGyrationSquared(section);
    const double polar2 = (sectionSecondMoment(section) + sectionSecondMomentOut(section)) / sectionArea(section);
    // The in-plane second moment's share of the polar one (the rotary inertia about z).
    const double in_share = sectionSecondMomentOut(section) > 0
                                ? sectionSecondMoment(section) / (sectionSecondMoment(section) + sectionSecondMomentOut(section))
                                : 0.5;
    SimTK::MobilizedBodyIndex prev;
    LinkAxis axis;
    axis.link = l.name;
    axis.length = l.length;
    for (std::size_t k = 0; k < d.pieces.size(); ++k) {
      // A planar link of the spatial article still moves out of the plane with it: its
      // pieces get their polar inertia when its section states I_out.
      const SimTK::Body::Rigid body = spatial() && (bendsOutOfPlane(l) || sectionSecondMomentOut(section) > 0)
                                          ? spatialPieceBody(d.pieces[k], polar2, in_share)
                                          : pieceBody(d.pieces[k], gyr2);
      SimTK::MobilizedBodyIndex ix;
      if (k == 0 && first) {
        ix = parent.grounded && a_.base.type == BaseType::Floating ? addFloatingRoot(j, l, parent, body)
                                                                    : addJointPin(j, l, parent, body);
        rotor = {ix, mountFrame(l)};
      } else if (k == 0) {
        SimTK::MobilizedBody::Weld w(matter.updMobilizedBody(rotor.mobod), rotor.mount, body, mountFrame(l));
        ix = w.getMobilizedBodyIndex();
      } else {
        ix = addHinge(l, d, k, prev, body);
      }
      model_.addBody(ix, part, false);
      if (k == 0) {
        axis.points.push_back(static_cast<int>(model_.getPoints().size()));
        model_.addPoint({l.name + ".root", ix, SimTK::Vec3(0), true});
        axis.x.push_back(0.0);
        axis.left.push_back(ix);
        axis.right.push_back(ix);
      } else {
        axis.points.push_back(static_cast<int>(model_.getPoints().size()) - 1);  // the hinge's point, just added
        axis.x.push_back(d.hinge_x[k - 1]);
        axis.left.push_back(prev);
        axis.right.push_back(ix);
      }
      prev = ix;
    }
    const SimTK::Transform X_tip(SimTK::Vec3(d.pieces.back().length, 0, 0));
    axis.points.push_back(static_cast<int>(model_.getPoints().size()));
    model_.addPoint({l.name + ".tip", prev, X_tip.p(), true});
    axis.x.push_back(l.length);
    axis.left.push_back(prev);
    axis.right.push_back(prev);
    model_.addLinkAxis(axis);
    if (l.tip_mass) {
      const int tip_part = model_.addPart(l.name + ".tip_mass", Part::Kind::TipMass, l.name);
      SimTK::MobilizedBody::Weld w(matter.updMobilizedBody(prev), X_tip, lumpedBody(*l.tip_mass), SimTK::Transform());
      model_.addBody(w.getMobilizedBodyIndex(), tip_part, false);
    }
    addStationMasses(l, axis);
    tips_[l.name] = Frame{prev, X_tip, false};
  }

  /// The link's station masses, each welded to the piece it lies on at its distance from
  /// the piece's start (a piece's frame starts at its hinge, x along the link).
  void addStationMasses(const LinkSpec& l, const LinkAxis& axis) {
    for (const auto& [x, mass] : l.station_masses) {
      MMV_DEMAND(x >= 0 && x <= l.length && mass > 0);
      const std::size_t k = axis.nodeBefore(x);  // its right-hand piece carries it
      const int part = model_.addPart(l.name + ".station_mass", Part::Kind::TipMass, l.name);
      SimTK::MobilizedBody::Weld w(model_.updMatter().updMobilizedBody(axis.right[k]),
                                   SimTK::Transform(SimTK::Vec3(x - axis.x[k], 0, 0)), lumpedBody(LumpedMass{mass, 0, {0, 0}}),
                                   SimTK::Transform());
      model_.addBody(w.getMobilizedBodyIndex(), part, false);
    }
  }

  /// The spatial model's stage across the plane (world z, the report's table y axis) on
  /// the x table, massless (its force column is what the article demands), held in
  /// statics and modes like the table and driven by its program in time runs.
  Frame buildTableZStage(const TableMotion& motion, SimTK::MobilizedBodyIndex table, int part, const Frame& on_table) {
    const SimTK::Rotation x_to_z(-SimTK::Pi / 2, SimTK::YAxis);  // the slider's x along world z
    SimTK::MobilizedBody::Slider stage(model_.updMatter().updMobilizedBody(table), SimTK::Transform(x_to_z),
                                       SimTK::Body::Massless(), SimTK::Transform(x_to_z));
    Coordinate c = sliderCoordinate("table.z", "table", stage.getMobilizedBodyIndex());
    c.axis = HingeAxis::OutOfPlane;  // an excitation out of the plane (the planarity report leaves it out)
    c.held = true;
    model_.addCoordinate(c);
    model_.addBody(stage.getMobilizedBodyIndex(), part, true);
    model_.setPrescribedMotion(c.mobod, prescribeTableProgram(stage, makeTableProgram(motion)));
    return Frame{stage.getMobilizedBodyIndex(), on_table.X_BF, true};
  }

  /// A floating root (component modes, free-free): rotation and both translations; in
  /// the spatial model all six (a Simbody bushing: x-y-z body-fixed rotations, then
  /// translations, q' = u), the in-plane three under the planar names.
  SimTK::MobilizedBodyIndex addFloatingRoot(const JointSpec& j, const LinkSpec& l, const Frame& parent,
                                            const SimTK::Body::Rigid& body) {
    auto& p = model_.updMatter().updMobilizedBody(parent.mobod);
    const SimTK::MobilizedBodyIndex ix =
        spatial() ? SimTK::MobilizedBody::Bushing(p, parent.X_BF, body, mountFrame(l)).getMobilizedBodyIndex()
                  : SimTK::MobilizedBody::Planar(p, parent.X_BF, body, mountFrame(l)).getMobilizedBodyIndex();
    struct Q {
      const char* suffix;
      bool rotation;
      int planar_q, spatial_q;  // -1: not in that model
    };
    constexpr Q qs[] = {{"", true, 0, 2},        {".x", false, 1, 3},       {".y", false, 2, 4},
                        {".roll", true, -1, 0},  {".pitch", true, -1, 1},   {".z", false, -1, 5}};
    for (const Q& q : qs) {
      const int mq = spatial() ? q.spatial_q : q.planar_q;
      if (mq < 0) continue;
      Coordinate coord;
      coord.name = j.name + q.suffix;
      coord.kind = CoordinateKind::Joint;
      coord.motion = q.rotation ? CoordinateMotion::Rotation : CoordinateMotion::Translation;
      coord.mobilizer_q = mq;
      coord.part = j.name;
      coord.mobod = ix;
      coord.reference = mq == (spatial() ? 2 : 0) ? j.angle : 0.0;
      model_.addCoordinate(coord);
    }
    return ix;
  }

  /// The joint's pin: locked (held, or following its slew), servo (a spring to the
  /// commanded angle) or free (with an optional commanded torque).
  SimTK::MobilizedBodyIndex addJointPin(const JointSpec& j, const LinkSpec& l, const Frame& parent,
                                        const SimTK::Body::Rigid& body) {
    SimTK::MobilizedBody::Pin pin(model_.updMatter().updMobilizedBody(parent.mobod), parent.X_BF, body, mountFrame(l));
    Coordinate coord;
    coord.name = j.name;
    coord.kind = CoordinateKind::Joint;
    coord.part = j.name;
    coord.mobod = pin.getMobilizedBodyIndex();
    coord.reference = j.angle;
    coord.held = j.hold == JointHold::Locked;
    coord.stiffness = j.hold == JointHold::Servo ? j.servo_stiffness : 0.0;
    if (j.torque_input) coord.input = makeTableProgram(*j.torque_input);
    model_.addCoordinate(coord);
    // A locked torquer holds its angle in the dynamics too (zero prescribed speed),
    // or follows its slew.
    if (coord.held) holdOrSlew(pin, j.angle, j.slew, j.continuous);
    return pin.getMobilizedBodyIndex();
  }

  bool spatial() const { return a_.model == ArticleModel::Spatial; }
  bool bendsOutOfPlane(const LinkSpec& l) const { return a_.bendsOutOfPlane(l); }

  /// Hinge k of a link: a pin with the bending spring E*I/h (and its damper); in the
  /// spatial model three body-fixed rotations (a Simbody Gimbal, q' = u): torsion about
  /// the link (G J / h), out-of-plane bending about the in-plane normal (E I_out / h),
  /// in-plane bending about z (E I / h, the planar hinge), named <link>.h<k>.twist,
  /// <link>.h<k>.out and <link>.h<k>, their springs on the rotation vector
  /// (sim/model/rotation_spring.hpp); a planar link (`model: planar` on a spatial
  /// article) keeps the pin.
  SimTK::MobilizedBodyIndex addHinge(const LinkSpec& l, const LinkDiscretization& d, std::size_t k,
                                     SimTK::MobilizedBodyIndex prev, const SimTK::Body::Rigid& body) {
    const SimTK::Transform X_PF(SimTK::Vec3(d.pieces[k - 1].length, 0, 0));
    auto& parent = model_.updMatter().updMobilizedBody(prev);
    const bool spatial_hinge = bendsOutOfPlane(l);
    const SimTK::MobilizedBodyIndex ix =
        spatial_hinge ? SimTK::MobilizedBody::Gimbal(parent, X_PF, body, SimTK::Transform()).getMobilizedBodyIndex()
                  : SimTK::MobilizedBody::Pin(parent, X_PF, body, SimTK::Transform()).getMobilizedBodyIndex();
    const std::string name = l.name + ".h" + std::to_string(k);
    const double k_in = d.hinge_stiffness[k - 1];
    if (spatial_hinge) {
      const Section& sec = *a_.findSection(l.section);
      const Material& mat = *a_.findMaterial(l.material);
      const double ei = mat.youngs_modulus * sectionSecondMoment(sec);
      model_.addHingeRotation(
          {hingeCoordinate(l, ix, name + ".twist", 0, k_in * mat.shear_modulus * sectionTorsionConstant(sec) / ei,
                           HingeAxis::Torsion),
           hingeCoordinate(l, ix, name + ".out", 1, k_in * sectionSecondMomentOut(sec) / sectionSecondMoment(sec),
                           HingeAxis::OutOfPlane),
           hingeCoordinate(l, ix, name, 2, k_in, HingeAxis::InPlane)});
    } else {
      model_.addCoordinate(hingeCoordinate(l, ix, name, 0, k_in, HingeAxis::InPlane));
    }
    model_.addPoint({name, ix, SimTK::Vec3(0), false});
    return ix;
  }

  Coordinate hingeCoordinate(const LinkSpec& l, SimTK::MobilizedBodyIndex ix, const std::string& name, int q,
                             double stiffness, HingeAxis axis) const {
    Coordinate coord;
    coord.name = name;
    coord.kind = CoordinateKind::Hinge;
    coord.part = l.name;
    coord.mobod = ix;
    coord.mobilizer_q = q;
    coord.axis = axis;
    coord.held = axis != HingeAxis::InPlane && a_.lock_out_of_plane;
    coord.stiffness = stiffness;
    if (scene_.damping && scene_.damping->kind == DampingSpec::Kind::HingeViscous)
      coord.damping = scene_.damping->hinge_beta * coord.stiffness;
    return coord;
  }

  LinkDiscretization discretize(const LinkSpec& l) const {
    const Material& mat = *a_.findMaterial(l.material);
    const Section& sec = *a_.findSection(l.section);
    return discretizeLink(l.length, mat.density * sectionArea(sec), mat.youngs_modulus * sectionSecondMoment(sec),
                          l.segments, l.rigid);
  }

  const ArticleScene& scene_;
  const ArticleSpec& a_;
  Model& model_;
  std::map<std::string, Frame> tips_;
  std::map<std::string, bool> built_joints_, queued_;
};

}  // namespace

std::unique_ptr<Model> buildArticleModel(const ArticleScene& scene, ModelUse use) {
  const auto& g = scene.gravity;
  auto model = std::make_unique<Model>(SimTK::Vec3(g[0], g[1], g[2]));
  for (const auto& l : scene.article.links)
    if (scene.article.linkModel(l) == ArticleModel::Spatial && scene.article.model != ArticleModel::Spatial)
      throw std::invalid_argument("link '" + l.name + "' bends out of its plane: the article's model must be spatial");
  if (scene.article.model == ArticleModel::Spatial) model->setSpatial();
  Builder(scene, *model).build();
  addLoadsAndClosures(scene.article, *model);
  if (use == ModelUse::TimeRun && scene.shaker && scene.shaker->program) addShakerArmature(scene, *model);
  model->setClosedFormForces();  // the builder adds nothing else (the damper below vanishes at rest)
  // A modal ratio or Rayleigh damping: a damping matrix over the free coordinates, set
  // by a time run at its equilibrium (sim/statics/damping_matrix.hpp).
  if (scene.damping && scene.damping->kind != DampingSpec::Kind::HingeViscous) model->addLinearDamper();
  if (std::any_of(scene.article.links.begin(), scene.article.links.end(), [](const LinkSpec& l) { return l.modal(); }))
    model->addReducedMotions();
  model->finalize();
  return model;
}

}  // namespace mmv

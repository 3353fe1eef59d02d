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
#include <optional>
#include <string>
#include <vector>

#include "article/section.hpp"

namespace mmv {

/// A point mass with rotary inertia about the out-of-plane axis through it.
struct LumpedMass {
  double mass = 0;            ///< kg, >= 0.
  double rotary_inertia = 0;  ///< kg*m^2 about z through the mass, >= 0.
};

/// How the joint's torquer holds the commanded angle during statics and modes.
enum class JointHold {
  Locked,  ///< Holds exactly (infinitely stiff servo): the joint is not a DOF.
  Free,    ///< Frictionless pin, no torque: the angle follows from equilibrium.
  Servo,   ///< A rotational spring of `servo_stiffness` pulling to the commanded angle.
};

struct JointSpec {
  std::string name;
  std::string parent;      ///< "base" or the name of a link (or branch) whose tip carries it.
  double angle = 0;        ///< commanded angle in rad.
  JointHold hold = JointHold::Locked;
  double servo_stiffness = 0;  ///< N*m/rad, > 0 when hold is Servo.
  std::optional<LumpedMass> torquer;  ///< lumped on the parent side (stator housing).
};

struct LinkSpec {
  std::string name;
  std::string joint;       ///< the joint at the link's root.
  std::string material;    ///< name of a Material.
  std::string section;     ///< name of a Section.
  double length = 0;       ///< m, > 0.
  int segments = 1;        ///< flexible elements per link (>= 1); ignored when rigid.
  bool rigid = false;      ///< one rigid body instead of a flexible chain.
  double mount_angle = 0;  ///< rad, link direction relative to the joint's rotor frame.
  std::optional<LumpedMass> tip_mass;  ///< rigidly attached at the tip.
};

enum class BaseType { Fixed };

struct BaseSpec {
  BaseType type = BaseType::Fixed;
  std::array<double, 3> position{0, 0, 0};  ///< m, world frame.
  double direction = 0;  ///< rad, world direction of a base joint's zero angle (from +x, ccw).
};

struct ArticleSpec {
  std::vector<Material> materials;
  std::vector<Section> sections;
  std::vector<JointSpec> joints;
  std::vector<LinkSpec> links;  ///< branches already expanded into separate links.
  BaseSpec base;

  const Material* findMaterial(const std::string& name) const;
  const Section* findSection(const std::string& name) const;
  const JointSpec* findJoint(const std::string& name) const;
  const LinkSpec* findLink(const std::string& name) const;
};

}  // namespace mmv

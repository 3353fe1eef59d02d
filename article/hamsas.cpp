#include "article/hamsas.hpp"

#include <cmath>
#include <stdexcept>

namespace mmv {

int SpatialSpec::bodyIndex(const std::string& name) const {
  for (std::size_t i = 0; i < bodies.size(); ++i)
    if (bodies[i].name == name) return static_cast<int>(i);
  return -1;
}

namespace {

Eigen::Matrix3d boxInertia(double m, double a, double b, double c) {
  return Eigen::Vector3d(m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12).asDiagonal();
}

/// Inertia of a point-like part of mass m at offset r from a reference, about the reference.
Eigen::Matrix3d parallelAxis(double m, const Eigen::Vector3d& r) {
  return m * (r.squaredNorm() * Eigen::Matrix3d::Identity() - r * r.transpose());
}

}  // namespace

SpatialSpec buildHamsas(const HamsasSpec& s) {
  for (const HamsasParameter& p : hamsasParameters()) {
    const double v = s.*p.field;
    const bool ok = std::isfinite(v) && (p.sign == HamsasParameter::Positive      ? v > 0
                                         : p.sign == HamsasParameter::NonNegative ? v >= 0
                                                                                  : true);
    if (!ok)
      throw std::invalid_argument(std::string("hamsas.") + p.key +
                                  (p.sign == HamsasParameter::Positive ? " must be > 0" : p.sign == HamsasParameter::NonNegative ? " must be >= 0" : " must be finite"));
  }
  if (s.lp_length >= s.ip_length) throw std::invalid_argument("hamsas.lp_length must be shorter than ip_length");

  SpatialSpec out;
  out.output_body = 1;
  out.bodies.push_back({"base", "base", 1.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity()});

  const double L = s.ip_length, l = s.lp_length;
  const double z_hang = L - l;
  const double z_sb = z_hang - s.sb_com_below_hang;
  const double z_mgas = z_sb + s.mgas_plane_above_sb_com;
  const double z_ot = z_mgas + s.ot_com_above_mgas;
  out.bodies.push_back({"optical_table", "ot", s.ot_mass, {0, 0, z_ot},
                        boxInertia(s.ot_mass, s.ot_size_x, s.ot_size_y, s.ot_size_z)});
  out.bodies.push_back({"spring_box", "sb", s.sb_mass, {0, 0, z_sb},
                        boxInertia(s.sb_mass, s.sb_size_x, s.sb_size_y, s.sb_size_z)});
  const int ot = 1, sb = 2;

  const Eigen::Vector3d pivots[4] = {{s.ip_diamond_x / 2, 0, 0}, {0, s.ip_diamond_y / 2, 0},
                                     {-s.ip_diamond_x / 2, 0, 0}, {0, -s.ip_diamond_y / 2, 0}};
  // IP leg: a thin tube from the pivot up to the top, and a disk counterweight below the pivot.
  const double mt = s.ip_leg_mass, mc = s.counterweight_mass, d = s.counterweight_depth;
  const double m_leg = mt + mc;
  const double zc = (mt * L / 2 - mc * d) / m_leg;  // mass centre above the pivot
  Eigen::Matrix3d I_leg = Eigen::Vector3d(mt * (s.ip_leg_radius * s.ip_leg_radius / 2 + L * L / 12),
                                          mt * (s.ip_leg_radius * s.ip_leg_radius / 2 + L * L / 12),
                                          mt * s.ip_leg_radius * s.ip_leg_radius)
                              .asDiagonal();
  I_leg += parallelAxis(mt, {0, 0, L / 2 - zc});
  const double rc = s.counterweight_radius;
  I_leg += Eigen::Vector3d(mc * rc * rc / 4, mc * rc * rc / 4, mc * rc * rc / 2).asDiagonal();
  I_leg += parallelAxis(mc, {0, 0, -d - zc});
  const Eigen::Matrix3d I_lp =
      Eigen::Vector3d(s.lp_mass * (l * l / 12 + s.lp_radius * s.lp_radius / 4),
                      s.lp_mass * (l * l / 12 + s.lp_radius * s.lp_radius / 4), s.lp_mass * s.lp_radius * s.lp_radius / 2)
          .asDiagonal();
  const Eigen::Vector3d kj = Eigen::Vector3d::Constant(s.joint_stiffness), cj = Eigen::Vector3d::Constant(s.joint_damping);
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i + 1);
    const Eigen::Vector3d& p = pivots[i];
    const int leg = static_cast<int>(out.bodies.size());
    out.bodies.push_back({"ip_leg" + n, "ip_leg", m_leg, p + Eigen::Vector3d(0, 0, zc), I_leg});
    const int lp = static_cast<int>(out.bodies.size());
    out.bodies.push_back({"lp" + n, "lp", s.lp_mass, p + Eigen::Vector3d(0, 0, L - l / 2), I_lp});
    out.springs.push_back({"flex_joint" + n, "joint", 0, leg, p, kj, cj, true});
    out.angular.push_back({"flex_joint" + n, "flex_joint", 0, leg,
                           {s.flex_stiffness, s.flex_stiffness, s.flex_torsion},
                           {s.flex_damping, s.flex_damping, 0.0}});
    out.springs.push_back({"leg_top" + n, "joint", leg, lp, p + Eigen::Vector3d(0, 0, L), kj, cj, true});
    out.springs.push_back({"lp_bottom" + n, "joint", lp, sb, p + Eigen::Vector3d(0, 0, z_hang), kj, cj, true});
    out.angular.push_back({"lp_torsion" + n, "lp_torsion", lp, sb, {0, 0, s.lp_torsion}, {0, 0, 0}});
  }
  for (int i = 0; i < 4; ++i) {
    const double x = (i == 0 || i == 3 ? 1 : -1) * s.mgas_rect_x / 2, y = (i < 2 ? 1 : -1) * s.mgas_rect_y / 2;
    out.springs.push_back({"mgas" + std::to_string(i + 1), "mgas", sb, ot, {x, y, z_mgas},
                           {s.mgas_horizontal_stiffness, s.mgas_horizontal_stiffness, s.mgas_vertical_stiffness},
                           {s.mgas_horizontal_damping, s.mgas_horizontal_damping, s.mgas_vertical_damping}, false});
  }
  // Sensors (and co-located actuators) on the spring box at each leg: tangential and vertical.
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d p(pivots[i].x(), pivots[i].y(), z_sb);
    const Eigen::Vector3d t = Eigen::Vector3d(-p.y(), p.x(), 0).normalized();
    out.sensors.push_back({"h" + std::to_string(i + 1), 0, sb, p, t});
  }
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d p(pivots[i].x(), pivots[i].y(), z_sb);
    out.sensors.push_back({"v" + std::to_string(i + 1), 0, sb, p, Eigen::Vector3d::UnitZ()});
  }
  return out;
}

const std::vector<HamsasParameter>& hamsasParameters() {
  using P = HamsasParameter;
  static const std::vector<HamsasParameter> params = {
      {"ip_diamond_x", &HamsasSpec::ip_diamond_x, P::Positive, " m"},
      {"ip_diamond_y", &HamsasSpec::ip_diamond_y, P::Positive, " m"},
      {"mgas_rect_x", &HamsasSpec::mgas_rect_x, P::Positive, " m"},
      {"mgas_rect_y", &HamsasSpec::mgas_rect_y, P::Positive, " m"},
      {"ip_length", &HamsasSpec::ip_length, P::Positive, " m"},
      {"ip_leg_mass", &HamsasSpec::ip_leg_mass, P::Positive, " kg"},
      {"ip_leg_radius", &HamsasSpec::ip_leg_radius, P::Positive, " m"},
      {"counterweight_mass", &HamsasSpec::counterweight_mass, P::NonNegative, " kg"},
      {"counterweight_depth", &HamsasSpec::counterweight_depth, P::NonNegative, " m"},
      {"counterweight_radius", &HamsasSpec::counterweight_radius, P::Positive, " m"},
      {"flex_stiffness", &HamsasSpec::flex_stiffness, P::Positive, " N*m/rad"},
      {"flex_torsion", &HamsasSpec::flex_torsion, P::Positive, " N*m/rad"},
      {"flex_damping", &HamsasSpec::flex_damping, P::NonNegative, " N*m*s/rad"},
      {"lp_length", &HamsasSpec::lp_length, P::Positive, " m"},
      {"lp_mass", &HamsasSpec::lp_mass, P::Positive, " kg"},
      {"lp_radius", &HamsasSpec::lp_radius, P::Positive, " m"},
      {"lp_torsion", &HamsasSpec::lp_torsion, P::Positive, " N*m/rad"},
      {"sb_mass", &HamsasSpec::sb_mass, P::Positive, " kg"},
      {"sb_size_x", &HamsasSpec::sb_size_x, P::Positive, " m"},
      {"sb_size_y", &HamsasSpec::sb_size_y, P::Positive, " m"},
      {"sb_size_z", &HamsasSpec::sb_size_z, P::Positive, " m"},
      {"sb_com_below_hang", &HamsasSpec::sb_com_below_hang, P::Any, " m"},
      {"mgas_plane_above_sb_com", &HamsasSpec::mgas_plane_above_sb_com, P::Any, " m"},
      {"ot_mass", &HamsasSpec::ot_mass, P::Positive, " kg"},
      {"ot_size_x", &HamsasSpec::ot_size_x, P::Positive, " m"},
      {"ot_size_y", &HamsasSpec::ot_size_y, P::Positive, " m"},
      {"ot_size_z", &HamsasSpec::ot_size_z, P::Positive, " m"},
      {"ot_com_above_mgas", &HamsasSpec::ot_com_above_mgas, P::Any, " m"},
      {"mgas_vertical_stiffness", &HamsasSpec::mgas_vertical_stiffness, P::Positive, " N/m"},
      {"mgas_horizontal_stiffness", &HamsasSpec::mgas_horizontal_stiffness, P::Positive, " N/m"},
      {"mgas_vertical_damping", &HamsasSpec::mgas_vertical_damping, P::NonNegative, " N*s/m"},
      {"mgas_horizontal_damping", &HamsasSpec::mgas_horizontal_damping, P::NonNegative, " N*s/m"},
      {"joint_stiffness", &HamsasSpec::joint_stiffness, P::Positive, " N/m"},
      {"joint_damping", &HamsasSpec::joint_damping, P::NonNegative, " N*s/m"},
  };
  return params;
}

}  // namespace mmv

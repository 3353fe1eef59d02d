#include "sim/io/vtk_export.hpp"

#include <cmath>
#include <map>
#include <sstream>

#include "article/section.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"
#include "sim/io/placement_geometry.hpp"
#include "sim/hamsas/spatial_linear.hpp"
#include "sim/io/report.hpp"

namespace mmv {
namespace {

/// A link's section as drawn: depth in the bending plane, width out of it (m).
std::pair<double, double> drawnSection(const Section& s) {
  switch (s.shape) {
    case SectionShape::Rectangle:
    case SectionShape::RectangularTube: return {s.h, s.b};
    case SectionShape::RoundRod: return {2 * s.radius, 2 * s.radius};
    case SectionShape::Explicit: break;
  }
  const double d = 2 * std::sqrt(sectionArea(s) / M_PI);
  return {d, d};
}

/// A PolyData file as VTK's XML writer lays it out in ascii: numbers separated by
/// spaces (doubles with 17 digits, so they read back exactly), strings as their bytes
/// each ended by 0. Arrays are added in any order and written in the file's.
class PolyData {
 public:
  using Cells = std::vector<std::vector<long>>;
  explicit PolyData(std::string what) : what_(std::move(what)) { MMV_DEMAND(what_.find("--") == std::string::npos); }  // XML comment

  void fieldFloats(const std::string& name, const std::vector<double>& v) {
    field_ << "      <Array type=\"Float64\" Name=\"" << name << "\" NumberOfTuples=\"" << v.size() << "\" format=\"ascii\">\n       "
           << numbers(v) << "\n      </Array>\n";
  }
  void fieldStrings(const std::string& name, const std::vector<std::string>& v) {
    field_ << "      <Array type=\"String\" Name=\"" << name << "\" NumberOfTuples=\"" << v.size() << "\" format=\"ascii\">\n       ";
    for (const std::string& s : v) {
      for (unsigned char c : s) field_ << ' ' << static_cast<int>(c);
      field_ << " 0";
    }
    field_ << "\n      </Array>\n";
  }
  void points(const std::vector<double>& xyz) { points_ = xyz; }
  void pointFloats(const std::string& name, int components, const std::vector<double>& v) {
    MMV_DEMAND(v.size() == points_.size() / 3 * static_cast<std::size_t>(components));
    point_ << dataArray("Float64", name, components) << numbers(v) << "\n        </DataArray>\n";
  }
  void pointInts(const std::string& name, const std::vector<long>& v) {
    MMV_DEMAND(v.size() == points_.size() / 3);
    point_ << dataArray("Int64", name, 1) << integers(v) << "\n        </DataArray>\n";
  }
  void verts(Cells c) { verts_ = std::move(c); }
  void lines(Cells c) { lines_ = std::move(c); }
  void polys(Cells c) { polys_ = std::move(c); }
  /// One value per cell, verts first, then lines, then polygons.
  void cellInts(const std::string& name, const std::vector<long>& v) {
    MMV_DEMAND(v.size() == verts_.size() + lines_.size() + polys_.size());
    cell_ << dataArray("Int64", name, 1) << integers(v) << "\n        </DataArray>\n";
  }

  std::string text(const std::string& active_vectors, const std::string& active_scalars) const {
    std::ostringstream os;
    os << "<?xml version=\"1.0\"?>\n<!-- mmvlab: " << what_ << " (docs/outputs.md) -->\n"
       << "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       << "  <PolyData>\n    <FieldData>\n" << field_.str() << "    </FieldData>\n"
       << "    <Piece NumberOfPoints=\"" << points_.size() / 3 << "\" NumberOfVerts=\"" << verts_.size() << "\" NumberOfLines=\""
       << lines_.size() << "\" NumberOfStrips=\"0\" NumberOfPolys=\"" << polys_.size() << "\">\n"
       << "      <Points>\n" << dataArray("Float64", "Points", 3) << numbers(points_) << "\n        </DataArray>\n      </Points>\n"
       << "      <PointData";
    if (!active_vectors.empty()) os << " Vectors=\"" << active_vectors << "\"";
    if (!active_scalars.empty()) os << " Scalars=\"" << active_scalars << "\"";
    os << ">\n" << point_.str() << "      </PointData>\n      <CellData>\n" << cell_.str() << "      </CellData>\n";
    for (const auto& [tag, cells] :
         {std::pair<const char*, const Cells*>{"Verts", &verts_}, {"Lines", &lines_}, {"Polys", &polys_}}) {
      if (cells == &polys_ && polys_.empty()) continue;  // the article's files have none
      std::vector<long> connectivity, offsets;
      for (const auto& cell : *cells) {
        connectivity.insert(connectivity.end(), cell.begin(), cell.end());
        offsets.push_back(static_cast<long>(connectivity.size()));
      }
      os << "      <" << tag << ">\n"
         << dataArray("Int64", "connectivity", 1) << integers(connectivity) << "\n        </DataArray>\n"
         << dataArray("Int64", "offsets", 1) << integers(offsets) << "\n        </DataArray>\n"
         << "      </" << tag << ">\n";
    }
    os << "    </Piece>\n  </PolyData>\n</VTKFile>\n";
    return os.str();
  }

 private:
  static std::string dataArray(const char* type, const std::string& name, int components) {
    return strf("        <DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"ascii\">\n         ", type,
                name.c_str(), components);
  }
  static std::string numbers(const std::vector<double>& v) {
    std::string s;
    for (double x : v) {
      MMV_DEMAND(std::isfinite(x));
      s += ' ' + strf("%.17g", x);
    }
    return s;
  }
  static std::string integers(const std::vector<long>& v) {
    std::string s;
    for (long x : v) s += ' ' + std::to_string(x);
    return s;
  }
  std::string what_;
  std::ostringstream field_, point_, cell_;
  std::vector<double> points_;
  Cells verts_, lines_, polys_;
};

std::string modeArrayName(int number, double frequency_hz, bool rigid, bool stable) {
  const std::string n = strf("mode%02d_", number);
  if (rigid) return n + "rigid";
  if (!stable) return n + "unstable";
  return n + strf("%.4gHz", frequency_hz);
}

/// Each link's points in the given order (root, hinges, tip) and the section they carry;
/// the points on no link (the joints).
struct LinkLines {
  PolyData::Cells lines;
  std::vector<std::string> names;
  std::vector<double> depth, width;  ///< per point (0 off the links)
  PolyData::Cells verts;
};

LinkLines linkLines(const std::vector<std::string>& names, const ArticleSpec& article) {
  const std::size_t np = names.size();
  LinkLines g;
  g.depth.assign(np, 0.0);
  g.width.assign(np, 0.0);
  std::vector<char> on_link(np, 0);
  for (const LinkSpec& l : article.links) {
    std::vector<long> line;
    for (std::size_t i = 0; i < np; ++i)
      if (names[i].rfind(l.name + ".", 0) == 0) line.push_back(static_cast<long>(i));
    if (line.size() < 2) continue;
    const Section* s = article.findSection(l.section);
    MMV_DEMAND(s != nullptr);
    const auto [d, w] = drawnSection(*s);
    for (long i : line) g.depth[i] = d, g.width[i] = w, on_link[i] = 1;
    g.lines.push_back(std::move(line));
    g.names.push_back(l.name);
  }
  for (std::size_t i = 0; i < np; ++i)
    if (!on_link[i]) g.verts.push_back({static_cast<long>(i)});
  return g;
}

/// The links over points already set: the sections' arrays, the joints as verts, a
/// polyline per link, `link_index` per cell and `link_names`.
void addLinks(PolyData& vtp, LinkLines g) {
  vtp.fieldStrings("link_names", g.names);
  vtp.pointFloats("section_depth_m", 1, g.depth);
  vtp.pointFloats("section_width_m", 1, g.width);
  std::vector<double> radius(g.depth);
  for (double& x : radius) x /= 2;
  vtp.pointFloats("tube_radius_m", 1, radius);
  std::vector<long> link_index(g.verts.size(), -1);
  for (std::size_t k = 0; k < g.lines.size(); ++k) link_index.push_back(static_cast<long>(k));
  vtp.verts(std::move(g.verts));
  vtp.lines(std::move(g.lines));
  vtp.cellInts("link_index", link_index);
}

}  // namespace

std::string modesVtp(const ModesReport& r, const ArticleSpec& article) {
  const std::size_t np = r.points.size();
  std::map<std::string, std::size_t> index;
  for (std::size_t i = 0; i < np; ++i) index[r.points[i].name] = i;
  std::vector<std::string> names;
  for (const PointReport& p : r.points) names.push_back(p.name);
  PolyData vtp("the article at its equilibrium and its modes, modes.vtp");
  std::vector<double> hz, zeta;
  for (const ModeInfo& m : r.modes) {
    hz.push_back(m.stable ? m.frequency_hz : -std::sqrt(std::max(-m.omega2, 0.0)) / (2 * M_PI));
    zeta.push_back(m.damping_ratio);
  }
  vtp.fieldFloats("frequency_hz", hz);
  if (r.damped) vtp.fieldFloats("damping_ratio", zeta);
  vtp.fieldStrings("scene", {r.scene_name, r.scene_source, std::string("mmvlab ") + mmvlabVersion()});
  std::vector<double> xyz, deflection;
  for (const PointReport& p : r.points) xyz.insert(xyz.end(), {p.x, p.y, p.z}), deflection.insert(deflection.end(), {p.dx, p.dy, p.dz});
  vtp.points(xyz);
  vtp.pointFloats("deflection_m", 3, deflection);
  addLinks(vtp, linkLines(names, article));
  for (const ModeInfo& m : r.modes) {
    std::vector<double> u(3 * np, 0.0);
    for (const PointMotion& p : m.shape) {
      const auto it = index.find(p.point);
      MMV_DEMAND(it != index.end());
      u[3 * it->second] = p.ux, u[3 * it->second + 1] = p.uy, u[3 * it->second + 2] = p.uz;
    }
    vtp.pointFloats(modeArrayName(m.number.number(), m.frequency_hz, m.rigid_body, m.stable), 3, u);
  }
  return vtp.text("deflection_m", "tube_radius_m");
}

std::string articlePoseVtp(const std::vector<std::string>& names, const std::vector<double>& xyz,
                           const std::vector<double>& displacement, const ArticleSpec& article, double time_s) {
  MMV_DEMAND(xyz.size() == 3 * names.size() && displacement.size() == xyz.size());
  PolyData vtp("the article at one time of a run, a frame of the run's .pvd collection");
  vtp.fieldFloats("TimeValue", {time_s});
  vtp.points(xyz);
  vtp.pointFloats("displacement_m", 3, displacement);
  addLinks(vtp, linkLines(names, article));
  return vtp.text("displacement_m", "tube_radius_m");
}

std::string pvdCollection(const std::vector<std::pair<double, std::string>>& frames) {
  std::string s = "<?xml version=\"1.0\"?>\n<!-- mmvlab: a run's frames for ParaView (docs/renders.md) -->\n"
                  "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [t, file] : frames) {
    MMV_DEMAND(std::isfinite(t) && file.find_first_of("\"<>&") == std::string::npos);
    s += strf("    <DataSet timestep=\"%.17g\" group=\"\" part=\"0\" file=\"%s\"/>\n", t, file.c_str());
  }
  return s + "  </Collection>\n</VTKFile>\n";
}

std::string placementVtp(const PlacementStudy& s) {
  const std::vector<PlacementChannel> channels = placementChannels(s);
  PolyData vtp("the chosen sensors, one point per channel, sensors.vtp");
  vtp.fieldFloats("target_frequency_hz", s.target_frequencies_hz);
  std::vector<std::string> stations;
  std::vector<double> xyz, direction;
  std::vector<long> channel, node, fixed;
  PolyData::Cells verts;
  for (const PlacementChannel& c : channels) {
    const PlacementCandidate& p = *c.candidate;
    verts.push_back({static_cast<long>(stations.size())});
    stations.push_back(p.station + " " + c.direction->axis);
    xyz.insert(xyz.end(), {p.world_x, p.world_y, p.world_z});
    direction.insert(direction.end(), c.direction->world.begin(), c.direction->world.end());
    channel.push_back(c.channel), node.push_back(p.node), fixed.push_back(p.fixed ? 1 : 0);
  }
  vtp.fieldStrings("channels", stations);
  vtp.fieldStrings("scene", {s.scene_name, std::string("mmvlab ") + mmvlabVersion()});
  vtp.points(xyz);
  vtp.pointFloats("direction", 3, direction);
  vtp.pointInts("channel", channel);
  vtp.pointInts("node", node);
  vtp.pointInts("kept_from_scene", fixed);
  for (std::size_t j = 0; j < s.target_modes.size(); ++j) {
    std::vector<double> u;
    for (const PlacementChannel& c : channels) u.insert(u.end(), c.candidate->shape[j].begin(), c.candidate->shape[j].end());
    vtp.pointFloats(modeArrayName(s.target_modes[j].number(), s.target_frequencies_hz[j], false, true), 3, u);
  }
  vtp.verts(std::move(verts));
  vtp.cellInts("channel", channel);
  return vtp.text("direction", "");
}

namespace {

/// The isolator's moving bodies (not the base, whose motion is prescribed) as their
/// equivalent boxes: 8 corners a body, corner k at the centre + side / 2 * (+-1, +-1,
/// +-1) by the bits of k (x, y, z), 6 faces wound outward.
struct HamsasBoxes {
  std::vector<Eigen::Vector3d> corners;  ///< at the design configuration, world
  std::vector<long> point_body, face_body;
  PolyData::Cells faces;
};

HamsasBoxes hamsasBoxes(const SpatialSpec& spec) {
  constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  HamsasBoxes g;
  for (std::size_t b = 1; b < spec.bodies.size(); ++b) {
    const Eigen::Vector3d half = 0.5 * equivalentBox(spec.bodies[b]);
    const long first = static_cast<long>(g.corners.size());
    for (int k = 0; k < 8; ++k) {
      g.corners.push_back(spec.bodies[b].com +
                          Eigen::Vector3d((k & 1) ? half.x() : -half.x(), (k & 2) ? half.y() : -half.y(), (k & 4) ? half.z() : -half.z()));
      g.point_body.push_back(static_cast<long>(b));
    }
    for (const auto& f : kFaces) {
      g.faces.push_back({first + f[0], first + f[1], first + f[2], first + f[3]});
      g.face_body.push_back(static_cast<long>(b));
    }
  }
  return g;
}

/// The boxes' faces and `body_index` (points and cells) and `body_names` over points
/// already set.
void addBoxes(PolyData& vtp, const SpatialSpec& spec, HamsasBoxes g) {
  std::vector<std::string> names;
  for (const SpatialBody& b : spec.bodies) names.push_back(b.name);
  vtp.fieldStrings("body_names", names);
  vtp.pointInts("body_index", g.point_body);
  vtp.polys(std::move(g.faces));
  vtp.cellInts("body_index", g.face_body);
}

std::vector<double> flat(const std::vector<Eigen::Vector3d>& v) {
  std::vector<double> xyz;
  for (const auto& p : v) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return xyz;
}

}  // namespace

std::string hamsasModesVtp(const HamsasScene& scene, const HamsasModes& h, int max_modes) {
  const SpatialSpec& spec = h.model;
  const int all = static_cast<int>(h.modes.size()), n = max_modes > 0 ? std::min(max_modes, all) : all;
  PolyData vtp("the isolator's bodies at the design configuration and its modes, modes.vtp");
  std::vector<double> hz;
  for (int i = 0; i < n; ++i) hz.push_back(h.modes[static_cast<std::size_t>(i)].frequency_hz);
  vtp.fieldFloats("frequency_hz", hz);
  vtp.fieldStrings("scene", {scene.name, scene.source, std::string("mmvlab ") + mmvlabVersion()});
  HamsasBoxes g = hamsasBoxes(spec);
  vtp.points(flat(g.corners));
  // A corner's translation per unit modal coordinate: the body's t + w x (corner - centre).
  for (int i = 0; i < n; ++i) {
    const Eigen::VectorXd phi = h.solution.shapes.col(i);
    std::vector<double> u;
    for (std::size_t p = 0; p < g.corners.size(); ++p) {
      const int b = static_cast<int>(g.point_body[p]);
      const int r = SpatialLinearization::row(b);
      const Eigen::Vector3d d = phi.segment<3>(r) + phi.segment<3>(r + 3).cross(g.corners[p] - spec.bodies[static_cast<std::size_t>(b)].com);
      u.insert(u.end(), {d.x(), d.y(), d.z()});
    }
    vtp.pointFloats(modeArrayName(i + 1, hz[static_cast<std::size_t>(i)], false, h.solution.isStable(i)), 3, u);
  }
  addBoxes(vtp, spec, std::move(g));
  return vtp.text(n > 0 ? modeArrayName(1, hz[0], false, h.solution.isStable(0)) : "", "");
}

std::vector<double> hamsasCorners(const SpatialSpec& spec, const std::vector<Eigen::Matrix<double, 6, 1>>& motion) {
  MMV_DEMAND(motion.size() == spec.bodies.size());
  HamsasBoxes g = hamsasBoxes(spec);
  for (std::size_t p = 0; p < g.corners.size(); ++p) {
    const auto& m = motion[static_cast<std::size_t>(g.point_body[p])];
    const Eigen::Vector3d com = spec.bodies[static_cast<std::size_t>(g.point_body[p])].com, w = m.tail<3>();
    const Eigen::Matrix3d R = w.norm() > 0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() : Eigen::Matrix3d::Identity();
    g.corners[p] = com + m.head<3>() + R * (g.corners[p] - com);
  }
  return flat(g.corners);
}

std::string hamsasPoseVtp(const SpatialSpec& spec, const std::vector<double>& xyz, const std::vector<double>& displacement,
                          double time_s) {
  HamsasBoxes g = hamsasBoxes(spec);
  MMV_DEMAND(xyz.size() == 3 * g.corners.size() && displacement.size() == xyz.size());
  PolyData vtp("the isolator at one time of a run, a frame of the run's .pvd collection");
  vtp.fieldFloats("TimeValue", {time_s});
  vtp.points(xyz);
  vtp.pointFloats("displacement_m", 3, displacement);
  addBoxes(vtp, spec, std::move(g));
  return vtp.text("displacement_m", "");
}

}  // namespace mmv

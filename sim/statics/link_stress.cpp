#include "sim/statics/link_stress.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "sim/core/errors.hpp"
#include "sim/model/rotation_spring.hpp"

namespace mmv {

SectionStrength sectionStrength(const Material& m, const Section& s) {
  SectionStrength out;
  out.area = sectionArea(s);
  out.second_moment = sectionSecondMoment(s);
  out.second_moment_out = sectionSecondMomentOut(s);
  out.fibre = sectionFibreDistance(s);
  out.fibre_out = sectionFibreDistanceOut(s);
  out.shear_per_torque = sectionTorsionShearPerTorque(s);
  out.round = s.shape == SectionShape::RoundRod;
  out.youngs_modulus = m.youngs_modulus;
  return out;
}

SectionStress sectionStress(const SectionStrength& s, const SectionLoads& l) {
  SectionStress out;
  const double n = s.area > 0 ? l.axial / s.area : 0.0;
  const double in = s.second_moment > 0 ? std::abs(l.moment) * s.fibre / s.second_moment : 0.0;
  const double off = s.second_moment_out > 0 ? std::abs(l.moment_out) * s.fibre_out / s.second_moment_out : 0.0;
  // A rod's two moments are one moment about a tilted axis; a rectangle's peak at a corner.
  const double bending = s.round ? std::hypot(in, off) : in + off;
  out.tension = n + bending;
  out.compression = n - bending;
  out.shear = std::abs(l.torsion) * s.shear_per_torque;
  const double peak = std::max(std::abs(out.tension), std::abs(out.compression));
  out.equivalent = std::sqrt(peak * peak + 3 * out.shear * out.shear);
  out.strain = s.youngs_modulus > 0 ? peak / s.youngs_modulus : 0.0;
  // Bending round-off beside the axial stress (a hanging link's hinges bent by 1e-25 rad)
  // names no face.
  if (!(bending > 1e-9 * std::abs(n))) {
    out.face = "axis";
    return out;
  }
  // The face where |sigma| peaks: the stretched one when the tension is the larger.
  const bool stretched = std::abs(out.tension) >= std::abs(out.compression);
  // A positive in-plane moment compresses +y; a positive out-of-plane one stretches +z.
  if (in > 0) out.face += (l.moment > 0) == stretched ? "-y" : "+y";
  if (off > 0) out.face += (l.moment_out > 0) == stretched ? "+z" : "-z";
  return out;
}

namespace {

/// The hinge nodes of a link: 1 .. size - 2 of its axis (0 is the root, the last the tip).
std::size_t hingeCount(const LinkAxis& axis) { return axis.x.size() >= 2 ? axis.x.size() - 2 : 0; }

/// A hinge's springs: its coordinates' linear ones, or a spatial hinge's rotation spring.
struct HingeSprings {
  std::vector<int> coords;
  const RotationSpring* rotation = nullptr;
};

/// Each hinge's springs, found by its mobilized body in one pass over the coordinates and
/// springs (a modes run asks this per mode and per link: linear, not per hinge).
std::vector<HingeSprings> hingeSprings(const Model& model, const LinkAxis& axis) {
  std::unordered_map<int, std::size_t> hinge_of;  // mobilized body -> hinge
  for (std::size_t k = 0; k < hingeCount(axis); ++k) hinge_of[static_cast<int>(axis.right[k + 1])] = k;
  std::vector<HingeSprings> out(hingeCount(axis));
  for (const RotationSpring& r : model.getRotationSprings())
    if (const auto it = hinge_of.find(static_cast<int>(r.mobod)); it != hinge_of.end()) out[it->second].rotation = &r;
  const auto& coords = model.getCoordinates();
  for (int c = 0; c < model.getNumCoordinates(); ++c) {
    if (coords[c].kind != CoordinateKind::Hinge) continue;
    if (const auto it = hinge_of.find(static_cast<int>(coords[c].mobod)); it != hinge_of.end()) out[it->second].coords.push_back(c);
  }
  return out;
}

}  // namespace

std::vector<SectionLoads> hingeMoments(const Model& model, const LinkAxis& axis, const Eigen::VectorXd& q) {
  MMV_DEMAND(q.size() == model.getNumCoordinates());
  const std::vector<HingeSprings> springs = hingeSprings(model, axis);
  std::vector<SectionLoads> out(springs.size());
  const auto& coords = model.getCoordinates();
  for (std::size_t k = 0; k < springs.size(); ++k) {
    out[k].x = axis.x[k + 1];
    if (const RotationSpring* r = springs[k].rotation) {
      const SimTK::Vec3 psi = rotationVector(SimTK::Vec3(q[r->coords[0]], q[r->coords[1]], q[r->coords[2]]));
      out[k].torsion = r->k[0] * psi[0];
      out[k].moment_out = r->k[1] * psi[1];
      out[k].moment = r->k[2] * psi[2];
      continue;
    }
    for (const int c : springs[k].coords) {
      const Coordinate& co = coords[c];
      const double m = co.stiffness * (q[c] - co.reference);
      if (co.axis == HingeAxis::InPlane) out[k].moment = m;
      if (co.axis == HingeAxis::OutOfPlane) out[k].moment_out = m;
      if (co.axis == HingeAxis::Torsion) out[k].torsion = m;
    }
  }
  return out;
}

std::vector<SectionLoads> hingeMomentRates(const Model& model, const LinkAxis& axis, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& dq) {
  MMV_DEMAND(dq.size() == q.size());
  const std::vector<SectionLoads> up = hingeMoments(model, axis, q + dq), down = hingeMoments(model, axis, q - dq);
  std::vector<SectionLoads> out(up.size());
  for (std::size_t k = 0; k < up.size(); ++k) {
    out[k].x = up[k].x;
    out[k].moment = (up[k].moment - down[k].moment) / 2;
    out[k].moment_out = (up[k].moment_out - down[k].moment_out) / 2;
    out[k].torsion = (up[k].torsion - down[k].torsion) / 2;
  }
  return out;
}

void setStaticAxialForces(const Model& model, const LinkAxis& axis, const SimTK::State& s,
                          const std::vector<PointForce>& closure_forces, std::vector<SectionLoads>& hinges) {
  MMV_DEMAND(hinges.size() == hingeCount(axis));
  const auto& matter = model.getMatter();
  const SimTK::Vec3 g = model.getGravity(s);
  // The external force on each mobilized body's subtree: its bodies' weights, the dead
  // loads and closure forces on them, summed from the leaves in (a body's index exceeds
  // its parent's), one pass over the tree.
  std::vector<SimTK::Vec3> subtree(static_cast<std::size_t>(matter.getNumBodies()), SimTK::Vec3(0));
  for (const BodyInfo& b : model.getBodies()) subtree[b.mobod] += matter.getMobilizedBody(b.mobod).getBodyMass(s) * g;
  for (const PointLoad& l : model.getPointLoads()) subtree[l.mobod] += l.force_W;
  for (const PointForce& f : closure_forces)
    if (f.body >= 0) subtree[model.getBodies()[f.body].mobod] += f.force_W;
  for (int ix = matter.getNumBodies() - 1; ix > 0; --ix)
    subtree[matter.getMobilizedBody(SimTK::MobilizedBodyIndex(ix)).getParentMobilizedBody().getMobilizedBodyIndex()] +=
        subtree[ix];
  for (std::size_t k = 0; k < hinges.size(); ++k) {
    const SimTK::MobilizedBodyIndex mobod = axis.right[k + 1];
    const SimTK::Vec3 e = matter.getMobilizedBody(mobod).getBodyRotation(s).x();
    hinges[k].axial = SimTK::dot(subtree[mobod], e);
  }
}

void setReactionAxialForces(const Model& model, const LinkAxis& axis, const SimTK::State& s,
                            const SimTK::Vector_<SimTK::SpatialVec>& reactions, std::vector<SectionLoads>& hinges) {
  MMV_DEMAND(hinges.size() == hingeCount(axis));
  const auto& matter = model.getMatter();
  for (std::size_t k = 0; k < hinges.size(); ++k) {
    const SimTK::MobilizedBodyIndex mobod = axis.right[k + 1];
    const SimTK::Vec3 e = matter.getMobilizedBody(mobod).getBodyRotation(s).x();
    hinges[k].axial = -SimTK::dot(reactions[mobod][1], e);
  }
}

SectionLoads rootReactionLoads(const Model& model, const LinkAxis& axis, const std::vector<const LinkAxis*>& branches,
                               const SimTK::State& s, const SimTK::Vector_<SimTK::SpatialVec>& reactions) {
  const auto& matter = model.getMatter();
  const SimTK::MobilizedBody& root = matter.getMobilizedBody(axis.right.front());
  const SimTK::Vec3 p_root = root.getBodyOriginLocation(s);
  // Each reaction acts at its mobilizer's M frame on the child: shifted to the root point.
  const auto at_root = [&](const SimTK::MobilizedBody& b) {
    const SimTK::Vec3 p_M = b.findStationLocationInGround(s, b.getOutboardFrame(s).p());
    return SimTK::shiftForceFromTo(reactions[b.getMobilizedBodyIndex()], p_M, p_root);
  };
  SimTK::SpatialVec f = at_root(root);
  for (const LinkAxis* other : branches) {
    const SimTK::MobilizedBody& first = matter.getMobilizedBody(other->right.front());
    if (first.getParentMobilizedBody().getMobilizedBodyIndex() == root.getMobilizedBodyIndex()) f -= at_root(first);
  }
  const SimTK::Rotation& R = root.getBodyRotation(s);
  SectionLoads out;  // what the link applies to its support: the reaction's negative
  out.axial = -SimTK::dot(f[1], R.x());
  out.torsion = -SimTK::dot(f[0], R.x());
  out.moment_out = -SimTK::dot(f[0], R.y());
  out.moment = -SimTK::dot(f[0], R.z());
  return out;
}

SectionLoads loadsAt(const std::vector<SectionLoads>& hinges, double x) {
  MMV_DEMAND(!hinges.empty());
  if (hinges.size() == 1) {
    SectionLoads l = hinges.front();
    l.x = x;
    return l;
  }
  std::size_t k = 0;  // the pair (k, k + 1) that brackets x, or the outer pair beyond the ends
  while (k + 2 < hinges.size() && hinges[k + 1].x <= x) ++k;
  const SectionLoads &a = hinges[k], &b = hinges[k + 1];
  const double t = (x - a.x) / (b.x - a.x);
  auto lerp = [t](double u, double v) { return u + t * (v - u); };
  SectionLoads l;
  l.x = x;
  l.axial = lerp(a.axial, b.axial);
  l.moment = lerp(a.moment, b.moment);
  l.moment_out = lerp(a.moment_out, b.moment_out);
  l.torsion = lerp(a.torsion, b.torsion);
  return l;
}

LinkStressPeak peakStress(const LinkSpec& link, const SectionStrength& section, const std::vector<SectionLoads>& hinges) {
  LinkStressPeak out;
  out.link = link.name;
  if (link.rigid || hinges.empty()) {
    out.why_not = "rigid link: stress not recovered";
    return out;
  }
  if (!(section.fibre > 0) || (!(section.fibre_out > 0) && std::any_of(hinges.begin(), hinges.end(), [](const SectionLoads& h) {
                                 return h.moment_out != 0;
                               }))) {
    out.why_not = "its section gives no fibre distance (fibre_distance, fibre_distance_out): stress not recovered";
    return out;
  }
  if (!(section.shear_per_torque > 0) &&
      std::any_of(hinges.begin(), hinges.end(), [](const SectionLoads& h) { return h.torsion != 0; })) {
    out.why_not = "its section gives no torsional shear (an explicit section): stress not recovered";
    return out;
  }
  out.recovered = true;
  std::vector<double> where{0.0};
  for (const SectionLoads& h : hinges) where.push_back(h.x);
  where.push_back(link.length);
  bool first = true;
  for (const double x : where) {
    const SectionLoads l = loadsAt(hinges, x);
    const SectionStress st = sectionStress(section, l);
    if (first || st.equivalent > out.stress.equivalent) {
      out.loads = l;
      out.stress = st;
      first = false;
    }
  }
  if (out.stress.face == "axis") {  // bending at round-off (a hanging link): reported as none, as no machine repeats it
    out.loads.moment = out.loads.moment_out = 0;
    out.stress = sectionStress(section, out.loads);
  }
  return out;
}

double faceBendingStress(const SectionStrength& s, const SectionLoads& l, const std::string& face) {
  MMV_DEMAND(face == "+y" || face == "-y" || face == "+z" || face == "-z");
  if (face[1] == 'y') return (face[0] == '+' ? -1 : 1) * l.moment * s.fibre / s.second_moment;
  return (face[0] == '+' ? 1 : -1) * l.moment_out * s.fibre_out / s.second_moment_out;
}

Eigen::RowVectorXd bendingStressRow(const Model& model, const LinkSpec& link, const SectionStrength& section, double x,
                                    const std::string& face, const Eigen::VectorXd& q, const std::vector<int>& dofs) {
  const LinkAxis* axis = model.findLinkAxis(link.name);
  MMV_DEMAND(axis != nullptr && hingeCount(*axis) > 0);
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(static_cast<Eigen::Index>(dofs.size()));
  Eigen::VectorXd dq = Eigen::VectorXd::Zero(q.size());
  for (std::size_t j = 0; j < dofs.size(); ++j) {
    const Coordinate& c = model.getCoordinates()[dofs[j]];
    if (c.kind != CoordinateKind::Hinge || c.part != link.name) continue;  // moves no spring of this link
    dq[dofs[j]] = 1;
    row[static_cast<Eigen::Index>(j)] = faceBendingStress(section, loadsAt(hingeMomentRates(model, *axis, q, dq), x), face);
    dq[dofs[j]] = 0;
  }
  return row;
}

double strengthLimit(const Material& m, const StrengthFactors& f) {
  double limit = 0;
  for (const auto& [allowable, factor] : {std::pair{m.yield_strength, f.yield_factor}, std::pair{m.ultimate_strength, f.ultimate_factor}})
    if (allowable > 0 && (limit == 0 || allowable / factor < limit)) limit = allowable / factor;
  return limit;
}

StrengthJudgement judgeStress(double stress, const Material& m, const StrengthFactors& f) {
  StrengthJudgement out;
  if (!(m.yield_strength > 0) && !(m.ultimate_strength > 0)) {
    out.note = "no allowable (materials." + m.name + " gives no yield_strength or ultimate_strength): margin not judged";
    return out;
  }
  if (!(stress > 0)) {
    out.note = "no stress: margin not judged";
    return out;
  }
  out.judged = true;
  bool first = true;
  auto consider = [&](const char* criterion, double allowable, double factor) {
    if (!(allowable > 0)) return;
    const double margin = allowable / (factor * stress) - 1;
    if (first || margin < out.margin) {
      out.criterion = criterion;
      out.allowable = allowable;
      out.factor = factor;
      out.margin = margin;
      first = false;
    }
  };
  consider("yield", m.yield_strength, f.yield_factor);
  consider("ultimate", m.ultimate_strength, f.ultimate_factor);
  out.pass = out.margin >= 0;
  return out;
}

std::vector<LinkStaticStress> staticLinkStress(const Model& model, const ArticleSpec& article, const SimTK::State& s,
                                               const Eigen::VectorXd& q, const std::vector<PointForce>& closure_forces) {
  std::vector<LinkStaticStress> out;
  for (const LinkSpec& l : article.links) {
    const Material& m = *article.findMaterial(l.material);
    const SectionStrength section = sectionStrength(m, *article.findSection(l.section));
    const LinkAxis* axis = model.findLinkAxis(l.name);
    MMV_DEMAND(axis != nullptr);
    std::vector<SectionLoads> hinges = hingeMoments(model, *axis, q);
    setStaticAxialForces(model, *axis, s, closure_forces, hinges);
    LinkStaticStress r;
    r.material = m.name;
    r.peak = peakStress(l, section, hinges);
    if (r.peak.recovered) r.judgement = judgeStress(r.peak.stress.equivalent, m, article.strength);
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<LinkStressPeak> modalLinkStress(const Model& model, const ArticleSpec& article, const Eigen::VectorXd& q,
                                            const Eigen::VectorXd& dq) {
  std::vector<LinkStressPeak> out;
  for (const LinkSpec& l : article.links) {
    const Material& m = *article.findMaterial(l.material);
    const LinkAxis* axis = model.findLinkAxis(l.name);
    MMV_DEMAND(axis != nullptr);
    out.push_back(peakStress(l, sectionStrength(m, *article.findSection(l.section)), hingeMomentRates(model, *axis, q, dq)));
  }
  return out;
}

}  // namespace mmv

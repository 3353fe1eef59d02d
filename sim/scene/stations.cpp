#include "sim/scene/stations.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace mmv {
namespace {

/// A finite number filling `text` exactly, optionally followed by the unit "m".
bool number(const std::string& text, double& value, bool& metres) {
  std::string t = text;
  metres = !t.empty() && t.back() == 'm';
  if (metres) t.pop_back();
  if (t.empty()) return false;
  char* end = nullptr;
  value = std::strtod(t.c_str(), &end);
  return *end == '\0' && std::isfinite(value);
}

}  // namespace

bool isStationName(const std::string& name) { return name.find('@') != std::string::npos; }

std::optional<StationSpec> parseStation(const std::string& name, const ArticleSpec& article, std::string& error) {
  const auto at = name.find('@');
  if (at == std::string::npos || at == 0) {
    error = "'" + name + "' is not a station (LINK@DIST m, LINK@FRACTION, optionally +OFFSETm, +OFFSETm+NORMALm)";
    return std::nullopt;
  }
  StationSpec s;
  s.name = name;
  s.link = name.substr(0, at);
  const LinkSpec* link = article.findLink(s.link);
  if (!link) {
    std::string known;
    for (const auto& l : article.links) known += (known.empty() ? "" : ", ") + l.name;
    error = "station '" + name + "': unknown link '" + s.link + "' (known: " + known + ")";
    return std::nullopt;
  }
  std::string where = name.substr(at + 1), offset;
  // The offset starts at a sign that does not follow an exponent's 'e'.
  for (std::size_t i = 1; i < where.size(); ++i)
    if ((where[i] == '+' || where[i] == '-') && where[i - 1] != 'e' && where[i - 1] != 'E') {
      offset = where.substr(i);
      where = where.substr(0, i);
      break;
    }
  double pos = 0;
  bool metres = false;
  if (!number(where, pos, metres)) {
    error = "station '" + name + "': expected a distance in m (e.g. " + s.link + "@1.2m) or a fraction (e.g. " + s.link +
            "@0.5) after '@'";
    return std::nullopt;
  }
  std::ostringstream range;
  range << link->length;
  if (metres) {
    if (pos < 0 || pos > link->length) {
      error = "station '" + name + "': " + where + " is outside " + s.link + " (0 to " + range.str() + " m)";
      return std::nullopt;
    }
    s.x = pos;
  } else {
    if (pos < 0 || pos > 1) {
      error = "station '" + name + "': fraction " + where + " is outside 0 to 1 (or give a distance in m, 0 to " +
              range.str() + " m)";
      return std::nullopt;
    }
    s.x = pos * link->length;
  }
  if (!offset.empty()) {
    // A second signed distance after the first's unit is the offset along the normal.
    std::string offset_z;
    const auto unit = offset.find('m');
    if (unit != std::string::npos && unit + 1 < offset.size()) {
      offset_z = offset.substr(unit + 1);
      offset = offset.substr(0, unit + 1);
    }
    bool offset_metres = false;
    if (!number(offset, s.offset, offset_metres) || !offset_metres) {
      error = "station '" + name + "': the offset across the section is a distance in m (e.g. +0.0127m; got " + offset + ")";
      return std::nullopt;
    }
    if (!offset_z.empty()) {
      const char sign = offset_z.front();
      if ((sign != '+' && sign != '-') || !number(offset_z, s.offset_z, offset_metres) || !offset_metres) {
        error = "station '" + name + "': the offset along the section's normal is a signed distance in m after the "
                "first (e.g. +0m+0.004m; got " + offset_z + ")";
        return std::nullopt;
      }
      if (article.model != ArticleModel::Spatial && s.offset_z != 0) {
        error = "station '" + name + "': an offset out of the plane (" + offset_z + ") needs model: spatial";
        return std::nullopt;
      }
    }
  }
  return s;
}

std::optional<bool> strainBendsOutOfPlane(const std::string& word) {
  if (word == "in") return false;
  if (word == "out") return true;
  return std::nullopt;
}

std::optional<StrainSpan> strainSpan(const ArticleSpec& article, const std::string& a, const std::string& b, std::string& why,
                                     bool out_of_plane) {
  if (out_of_plane && article.model != ArticleModel::Spatial) {
    why = "the planar model does not bend out of its plane: a strain out of the plane needs the spatial article (model: spatial)";
    return std::nullopt;
  }
  std::optional<StationSpec> sa, sb;
  for (const auto& [name, spec] : {std::pair{&a, &sa}, std::pair{&b, &sb}}) {
    if (!isStationName(*name)) {
      why = "a strain spans two stations of one link, e.g. link3a@0.1m and link3a@0.3m (got '" + *name + "')";
      return std::nullopt;
    }
    *spec = parseStation(*name, article, why);
    if (!*spec) return std::nullopt;
    if ((*spec)->offset != 0 || (*spec)->offset_z != 0) {
      why = "give the stations on the link's axis, without an offset ('" + *name + "'); the face is the section's";
      return std::nullopt;
    }
  }
  if (sa->link != sb->link) {
    why = "both stations must be on one link (got " + sa->link + " and " + sb->link + ")";
    return std::nullopt;
  }
  if (std::abs(sb->x - sa->x) < 1e-6) {
    why = "the span is empty: give two different stations";
    return std::nullopt;
  }
  const LinkSpec& link = *article.findLink(sa->link);
  if (link.rigid) {
    why = link.name + " is rigid (segments: rigid): it does not bend";
    return std::nullopt;
  }
  if (out_of_plane && !article.bendsOutOfPlane(link)) {
    why = link.name + " is planar in this spatial article (its model: planar): it does not bend out of its plane";
    return std::nullopt;
  }
  const Section& s = *article.findSection(link.section);
  const double c = s.shape == SectionShape::RoundRod ? s.radius : s.shape == SectionShape::Explicit ? 0.0 : 0.5 * (out_of_plane ? s.b : s.h);
  if (!(c > 0)) {
    why = "section '" + s.name + "' of " + link.name + " gives no " + (out_of_plane ? "width" : "depth") + " (an explicit section): give its shape";
    return std::nullopt;
  }
  return StrainSpan{sa->link, sa->x, sb->x, c, out_of_plane};
}

std::optional<std::pair<std::string, double>> pointAlongLink(const ArticleSpec& a, const std::string& target, std::string& why) {
  if (isStationName(target)) {
    const std::optional<StationSpec> st = parseStation(target, a, why);
    if (st) return std::make_pair(st->link, st->x);
    return std::nullopt;
  }
  const auto dot = target.rfind('.');
  const LinkSpec* link = dot == std::string::npos ? nullptr : a.findLink(target.substr(0, dot));
  const std::string end = dot == std::string::npos ? "" : target.substr(dot + 1);
  if (link && (end == "tip" || end == "root")) return std::make_pair(link->name, end == "tip" ? link->length : 0.0);
  why = link ? "'" + target + "' is a point of the mesh, which moves along the link when the segments change: give it as a station"
             : "'" + target + "' is not on a link (a joint's axis): give a station";
  return std::nullopt;
}

}  // namespace mmv

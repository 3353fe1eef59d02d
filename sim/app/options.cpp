#include "sim/app/options.hpp"

#include <algorithm>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv::app {

std::vector<std::string> Option::choiceList() const { return choices_.empty() ? std::vector<std::string>{} : split(choices_, ','); }

std::string Option::cliFlag() const {
  if (!flag_.empty()) return flag_;
  std::string f = "--" + key_;
  std::replace(f.begin(), f.end(), '_', '-');
  return f;
}

bool Option::allows(double v) const {
  if (hasOff() && v == off_) return true;
  return std::isfinite(v) && (open_low_ ? v > lo_ : v >= lo_) && (open_high_ ? v < hi_ : v <= hi_);
}

std::string Option::rangeText() const {
  if (!hasRange()) return "";
  std::string r;
  const std::string high = (open_high_ ? "below " : "at most ") + shortest(hi_);
  if (std::isfinite(lo_) && std::isfinite(hi_) && !open_low_ && !open_high_)
    r = shortest(lo_) + " .. " + shortest(hi_);
  else if (std::isfinite(lo_))
    r = (open_low_ ? "above " : "at least ") + shortest(lo_) + (std::isfinite(hi_) ? ", " + high : "");
  else
    r = high;
  return hasOff() ? shortest(off_) + " (" + off_meaning_ + ") or " + r : r;
}

std::string Option::helpText(const std::string& default_text) const {
  std::vector<std::string> parts;
  if (!unit_.empty()) parts.push_back(unit_);
  if (!choices_.empty()) {
    std::string list;
    for (const auto& c : choiceList()) list += (list.empty() ? "" : ", ") + c;
    parts.push_back("one of " + list);
  }
  if (hasRange()) parts.push_back(rangeText());
  if (default_text.empty() && !absent_.empty())
    parts.push_back("default " + absent_);
  else if (!default_text.empty())
    parts.push_back("default " + default_text + (hasOff() && default_text == shortest(off_) ? " (" + off_meaning_ + ")" : ""));
  std::string bracket;
  for (const auto& p : parts) bracket += (bracket.empty() ? "" : "; ") + p;
  return bracket.empty() ? help_ : help_ + " [" + bracket + "]";
}

nlohmann::json optionValueJson(bool v) { return v; }
nlohmann::json optionValueJson(int v) { return v; }
nlohmann::json optionValueJson(double v) { return v; }
nlohmann::json optionValueJson(const std::string& v) { return v; }
nlohmann::json optionValueJson(const std::vector<std::string>& v) { return v; }
nlohmann::json optionValueJson(const std::vector<int>& v) { return v; }
nlohmann::json optionValueJson(const std::vector<double>& v) { return v; }
nlohmann::json optionValueJson(const Band& v) { return nlohmann::json::array({v.min_hz, v.max_hz}); }

std::string defaultText(const nlohmann::json& value, const std::string& type) {
  if (type == "band") return shortest(value[0].get<double>()) + ":" + shortest(value[1].get<double>());
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) return shortest(value.get<double>());
  if (value.is_null()) return "";  // absent: Option::helpText says what that means
  if (value.is_string()) return value.get<std::string>().empty() ? "" : value.get<std::string>();
  if (value.is_array()) {
    std::string list;
    for (const auto& v : value) list += (list.empty() ? "" : ",") + defaultText(v, v.is_string() ? "str" : "float");
    return list;
  }
  return "";
}

namespace {

std::string named(Front front, const Option& o) { return front == Front::Cli ? o.cliFlag() : o.key(); }

void checkNumber(Front front, const Option& o, double v, const std::string& shown) {
  if (o.allows(v)) return;
  if (!o.hasRange())
    throw UsageError(named(front, o) + ": must be a finite number (got " + shown + ")");
  throw UsageError(named(front, o) + ": must be " + (o.hasOff() ? shortest(o.offValue()) + " (" + o.offMeaning() + ") or " : "") +
                   "a finite number " +
                   (std::isfinite(o.lo()) ? (o.openLow() ? "above " : "of at least ") + shortest(o.lo()) : std::string()) +
                   (std::isfinite(o.lo()) && std::isfinite(o.hi()) ? " and " : "") +
                   (std::isfinite(o.hi()) ? (o.openHigh() ? "below " : "at most ") + shortest(o.hi()) : std::string()) +
                   " (got " + shown + ")");
}

}  // namespace

void checkOption(Front, const Option&, bool) {}
void checkOption(Front front, const Option& o, int v) { checkNumber(front, o, v, std::to_string(v)); }
void checkOption(Front front, const Option& o, double v) { checkNumber(front, o, v, strf("%g", v)); }

void checkOption(Front front, const Option& o, const std::string& v) {
  const std::vector<std::string> known = o.choiceList();
  if (known.empty() || std::find(known.begin(), known.end(), v) != known.end()) return;
  std::string list;
  for (const auto& c : known) list += (list.empty() ? "" : ", ") + c;
  throw UsageError(named(front, o) + ": unknown value '" + printable(v) + "'" + didYouMean(v, known) + " (known: " + list + ")");
}

void checkOption(Front front, const Option& o, const std::vector<std::string>& v) {
  for (const auto& s : v) checkOption(front, o, s);
}
void checkOption(Front front, const Option& o, const std::vector<int>& v) {
  for (int x : v) checkOption(front, o, x);
}
void checkOption(Front front, const Option& o, const std::vector<double>& v) {
  for (double x : v) checkOption(front, o, x);
}

void checkOption(Front front, const Option& o, const Band& b) {
  if (std::isfinite(b.min_hz) && std::isfinite(b.max_hz) && b.min_hz >= 0 && b.min_hz < b.max_hz) return;
  throw UsageError(strf("%s: expected 0 <= F_MIN_HZ < F_MAX_HZ (got %g:%g)", named(front, o).c_str(), b.min_hz, b.max_hz));
}

}  // namespace mmv::app

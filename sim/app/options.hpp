#pragma once
/// A verb's options, declared once (issue 63). Each verb's options struct lists its fields
/// in one static `fields(self, visit)`: the field, its Python keyword, its help sentence,
/// its unit and its range. From that one list:
///
/// - the study checks every value, once (`checkOptions`), naming the option as the front
///   end spells it (`--target-error` / `target_error`);
/// - the command line's options, help text and parsing are made by one adapter
///   (sim/cli/declared_options.hpp), the Python keywords, defaults and docstrings by
///   another (python/declared_options.hpp over `describeOptions`);
/// - a verb's registry entry (sim/app/verbs.hpp) names it for both.
///
/// The shape follows Drake's `Serialize(Archive*)` and Pinocchio's visitors: the struct is
/// plain data with its defaults as member initializers (the one place a default is
/// written), and the visitor decides what a field means to it.
///
///   struct ConvergeParams {
///     int max_segments = 64;
///     template <class S, class V> static void fields(S& s, V&& v) {
///       v(s.max_segments, Option("max_segments", "Finest segment count").range(1, 1024));
///     }
///   };

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/app/study.hpp"

namespace mmv::app {

/// F_MIN:F_MAX in Hz (the command line's "0.1:50", Python's (0.1, 50.0)); checked as
/// 0 <= min < max by `checkOptions`.
struct Band {
  double min_hz = 0, max_hz = 0;
  bool operator==(const Band& o) const { return min_hz == o.min_hz && max_hz == o.max_hz; }
};

/// What one declared field is, for the adapters and the check. Built in a chain:
/// Option("modes", "Modes to report (0: all)").atLeast(0).
class Option {
 public:
  Option(std::string key, std::string help) : key_(std::move(key)), help_(std::move(help)) {}

  /// Numbers (and each number of a list): lo <= value <= hi.
  Option& range(double lo, double hi) { lo_ = lo, hi_ = hi; return *this; }
  Option& atLeast(double lo) { return range(lo, std::numeric_limits<double>::infinity()); }
  /// lo < value <= hi.
  Option& above(double lo, double hi = std::numeric_limits<double>::infinity()) { open_low_ = true; return range(lo, hi); }
  /// value < hi: the bound itself is out (an accuracy in (0, 1)).
  Option& below(double hi) { open_high_ = true, hi_ = hi; return *this; }
  /// What an absent value means, for a field that may be absent (std::optional): "the
  /// scene's".
  Option& whenAbsent(const char* meaning) { absent_ = meaning; return *this; }
  /// A value outside the range that means "not asked" (0 for a target that is off).
  Option& off(double value, const char* meaning = "off") { off_ = value, off_meaning_ = meaning; return *this; }
  Option& unit(const char* u) { unit_ = u; return *this; }
  /// Text: one of these (comma-separated), checked by `checkOptions`.
  Option& choices(const char* list) { choices_ = list; return *this; }
  /// The command line's spelling where it is not "--" + key with '-' for '_'.
  Option& flag(const char* f) { flag_ = f; return *this; }
  /// A bool whose command-line flag `f` sets it false (error_estimate: --no-error-estimate),
  /// with that flag's own help sentence.
  Option& negated(const char* f, const char* cli_help) { flag_ = f, negated_help_ = cli_help, negated_ = true; return *this; }
  /// Lists: the command line splits one value at commas ("--points a,b"); without it the
  /// option is repeated for more items.
  Option& commaSeparated() { comma_ = true; return *this; }
  /// Required: the command line refuses to run without it, Python takes it positionally.
  Option& required() { required_ = true; return *this; }

  const std::string& key() const { return key_; }
  const std::string& help() const { return help_; }
  const std::string& unitName() const { return unit_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }
  bool openLow() const { return open_low_; }
  bool openHigh() const { return open_high_; }
  const std::string& absentMeaning() const { return absent_; }
  bool hasRange() const { return std::isfinite(lo_) || std::isfinite(hi_); }
  bool hasOff() const { return !std::isnan(off_); }
  double offValue() const { return off_; }
  const std::string& offMeaning() const { return off_meaning_; }
  std::vector<std::string> choiceList() const;
  bool negatedFlag() const { return negated_; }
  const std::string& negatedHelp() const { return negated_help_; }
  bool isCommaSeparated() const { return comma_; }
  bool isRequired() const { return required_; }
  /// "--target-error", or the declared spelling.
  std::string cliFlag() const;

  /// Whether `v` is allowed (the off value, or within the range).
  bool allows(double v) const;
  /// "at least 0", "0 .. 0.5 (0: off)", "above 0": the range as both fronts show it; ""
  /// for none.
  std::string rangeText() const;
  /// The help sentence with its unit, choices, range and `default_text` appended, as both
  /// the command line's --help and Python's docstring show it.
  std::string helpText(const std::string& default_text) const;

 private:
  std::string key_, help_, unit_, choices_, flag_, off_meaning_, negated_help_, absent_;
  double lo_ = -std::numeric_limits<double>::infinity(), hi_ = std::numeric_limits<double>::infinity();
  double off_ = std::numeric_limits<double>::quiet_NaN();
  bool open_low_ = false, open_high_ = false, negated_ = false, comma_ = false, required_ = false;
};

/// The field types a declaration may hold, as both adapters name them.
template <class T> struct OptionType;
template <> struct OptionType<bool> { static constexpr const char* name = "bool"; };
template <> struct OptionType<int> { static constexpr const char* name = "int"; };
template <> struct OptionType<double> { static constexpr const char* name = "float"; };
template <> struct OptionType<std::string> { static constexpr const char* name = "str"; };
template <> struct OptionType<std::vector<std::string>> { static constexpr const char* name = "list[str]"; };
template <> struct OptionType<std::vector<int>> { static constexpr const char* name = "list[int]"; };
template <> struct OptionType<std::vector<double>> { static constexpr const char* name = "list[float]"; };
template <> struct OptionType<Band> { static constexpr const char* name = "band"; };
/// A field that may be absent (the scene's setting holds): "float?" and so on.
template <> struct OptionType<std::optional<double>> { static constexpr const char* name = "float?"; };
template <> struct OptionType<std::optional<int>> { static constexpr const char* name = "int?"; };
template <> struct OptionType<std::optional<std::string>> { static constexpr const char* name = "str?"; };

/// A field's value as JSON (a Band as [min, max]).
nlohmann::json optionValueJson(bool v);
nlohmann::json optionValueJson(int v);
nlohmann::json optionValueJson(double v);
nlohmann::json optionValueJson(const std::string& v);
nlohmann::json optionValueJson(const std::vector<std::string>& v);
nlohmann::json optionValueJson(const std::vector<int>& v);
nlohmann::json optionValueJson(const std::vector<double>& v);
nlohmann::json optionValueJson(const Band& v);
/// null when absent.
template <class T>
nlohmann::json optionValueJson(const std::optional<T>& v) {
  return v ? optionValueJson(*v) : nlohmann::json();
}
/// The default as the help text shows it ("12", "0.1:50", "efi", "none").
std::string defaultText(const nlohmann::json& value, const std::string& type);

/// One declared option with its type and default: what the adapters are made from.
struct OptionDescription {
  Option option;
  std::string type;            ///< OptionType<T>::name
  nlohmann::json default_value;
  std::string help_text;       ///< Option::helpText with the default
};

/// Every option of `Options` in declaration order, with the defaults of a
/// default-constructed `Options`.
template <class Options>
std::vector<OptionDescription> describeOptions() {
  std::vector<OptionDescription> out;
  const Options defaults{};
  Options::fields(defaults, [&](const auto& field, const Option& o) {
    using T = std::decay_t<decltype(field)>;
    const nlohmann::json d = optionValueJson(field);
    out.push_back({o, OptionType<T>::name, d, o.helpText(defaultText(d, OptionType<T>::name))});
  });
  return out;
}

/// The check of one value against its declaration (UsageError naming it as `front`
/// spells it); the overloads for types without ranges check choices or nothing.
void checkOption(Front front, const Option& o, bool v);
void checkOption(Front front, const Option& o, int v);
void checkOption(Front front, const Option& o, double v);
void checkOption(Front front, const Option& o, const std::string& v);
void checkOption(Front front, const Option& o, const std::vector<std::string>& v);
void checkOption(Front front, const Option& o, const std::vector<int>& v);
void checkOption(Front front, const Option& o, const std::vector<double>& v);
void checkOption(Front front, const Option& o, const Band& v);
/// An absent value is not checked: the scene's setting holds.
template <class T>
void checkOption(Front front, const Option& o, const std::optional<T>& v) {
  if (v) checkOption(front, o, *v);
}

/// Every declared value of `options` checked once against its declaration; the study
/// calls it first and checks only what crosses fields or needs the scene after it.
template <class Options>
void checkOptions(const Options& options, Front front) {
  Options::fields(options, [&](const auto& field, const Option& o) { checkOption(front, o, field); });
}

/// The option `key` names in `Options` as `front` spells it ("--no-error-estimate",
/// "error_estimate"): for the messages of checks that cross fields. A key no field
/// declares is a bug (std::logic_error).
template <class Options>
std::string declaredName(const std::string& key, Front front) {
  std::string found;
  const Options defaults{};
  Options::fields(defaults, [&](const auto&, const Option& o) {
    if (o.key() == key) found = front == Front::Cli ? o.cliFlag() : o.key();
  });
  if (found.empty()) throw std::logic_error("declaredName: no option '" + key + "'");
  return found;
}

}  // namespace mmv::app

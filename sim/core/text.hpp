#pragma once
/// A table of strings rendered as aligned text (terminal) or as a Markdown table, so
/// each report is written once for both.

#include <string>
#include <vector>

namespace mmv {

class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  /// Columns aligned, numbers (cells starting with a digit, sign or dot) to the right.
  std::string text(const std::string& indent = "  ") const;
  std::string markdown() const;
  bool empty() const { return rows_.empty(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// The shortest decimal text that reads back as exactly `v` (std::to_chars):
/// 0.0025, not 0.0025000000000000001.
std::string shortest(double v);

/// " (did you mean 'x'?)" for the entry of `known` closest to `name` (at most two
/// edits away, Levenshtein; all entries at that distance, up to four: " (did you mean
/// 'a', 'b' or 'c'?)"), or "" when none is that close.
/// `s` cut at every `sep` ("a:b" gives a, b; "a:" gives a only, as std::getline does).
std::vector<std::string> split(const std::string& s, char sep);
std::string didYouMean(const std::string& name, const std::vector<std::string>& known);

/// `s` safe to print on a terminal: control bytes and bytes that are not valid UTF-8
/// become \xNN (a user's file name or value is echoed, never raw bytes).
std::string printable(const std::string& s);

/// Whether `s` is valid UTF-8 (what JSON and every text output need).
bool isValidUtf8(const std::string& s);

/// A CSV column name that numpy's genfromtxt(names=True), pandas and MATLAB's readtable
/// keep as it is: [a-z0-9_] only, every other run of characters one '_' (no '.', ':',
/// '/', '^'), lower case, never starting with a digit or '_' ("link3a.tip:x" ->
/// "link3a_tip_x", "gimbal.yaw_angle_deg" -> "gimbal_yaw_angle_deg").
std::string csvColumnName(const std::string& s);

/// A text cell that every CSV reader splits right, quoted or not (numpy's genfromtxt and
/// Octave's csvread do not honour quotes): ',' becomes ';' and '"' becomes '\''.
std::string csvEscape(const std::string& s);

/// A unit as a column-name suffix: "m/s^2" -> "m_s2", "N*m" -> "n_m", "rad/s" -> "rad_s".
std::string unitSlug(const std::string& unit);

/// printf into a std::string.
/// `s` with every character but letters and digits made '_': a scene key as part of a
/// file name ("links.link1.length" -> "links_link1_length").
std::string fileNameSafe(std::string s);

std::string strf(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace mmv

#include "sim/io/uff_read.hpp"

#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <vector>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv::uff {
namespace {

std::string trimmed(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

bool isDelimiter(const std::string& line) { return trimmed(line) == "-1" && line.find("-1") < 6; }

/// A number as FORTRAN writes it (E or D exponent); false unless all of `t` is one.
bool parseReal(std::string t, double& v) {
  t = trimmed(t);
  if (t.empty()) return false;
  for (char& c : t)
    if (c == 'D' || c == 'd') c = 'E';
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end == t.c_str() + t.size() && std::isfinite(v);
}

/// The lines of one file and where the reader is, with messages that point at them.
class Cursor {
 public:
  Cursor(const std::string& text, std::string source) : source_(std::move(source)) {
    std::istringstream is(text);
    for (std::string l; std::getline(is, l);) {
      if (!l.empty() && l.back() == '\r') l.pop_back();
      lines_.push_back(l);
    }
  }
  bool done() const { return at_ >= lines_.size(); }
  int lineNumber() const { return static_cast<int>(at_); }  ///< 1-based number of the line last taken.
  const std::string& peek() const { return lines_[at_]; }
  void skip() { ++at_; }
  void setContext(const std::string& c) { context_ = c; }

  [[noreturn]] void fail(std::size_t column, const std::string& what, const std::string& got = "") const {
    std::string msg = source_ + ":" + std::to_string(at_) + ":" + std::to_string(column + 1) + ": " + context_ + what;
    if (!got.empty()) msg += " (got '" + printable(trimmed(got)) + "')";
    throw SceneError(msg);
  }
  /// The next line of the dataset; failing at the file's end or at its closing -1.
  const std::string& next(const std::string& record) {
    if (at_ >= lines_.size()) fail(0, "the file ends inside " + record);
    if (isDelimiter(lines_[at_])) {
      ++at_;
      fail(0, "the dataset ends (-1) where " + record + " was expected");
    }
    return lines_[at_++];
  }
  /// Skips to the line after the dataset's closing -1.
  void closeDataset() {
    while (at_ < lines_.size() && !isDelimiter(lines_[at_])) ++at_;
    if (at_ >= lines_.size()) fail(0, "the file ends before the dataset's closing -1");
    ++at_;
  }
  bool atClose() const { return at_ < lines_.size() && isDelimiter(lines_[at_]); }

  static std::string field(const std::string& s, std::size_t pos, std::size_t n) {
    return pos < s.size() ? s.substr(pos, n) : std::string();
  }
  /// An integer in columns pos+1..pos+n (blank reads as 0, as FORTRAN reads it).
  int integer(const std::string& s, std::size_t pos, std::size_t n, const std::string& what) const {
    const std::string t = trimmed(field(s, pos, n));
    if (t.empty()) return 0;
    char* end = nullptr;
    const long v = std::strtol(t.c_str(), &end, 10);
    if (end != t.c_str() + t.size() || v < -2147483647L || v > 2147483647L)
      fail(pos, what + " must be an integer in columns " + std::to_string(pos + 1) + "-" + std::to_string(pos + n), t);
    return static_cast<int>(v);
  }
  double real(const std::string& s, std::size_t pos, std::size_t n, const std::string& what) const {
    const std::string t = field(s, pos, n);
    if (trimmed(t).empty()) return 0.0;
    double v = 0;
    if (!parseReal(t, v))
      fail(pos, what + " must be a finite number in columns " + std::to_string(pos + 1) + "-" + std::to_string(pos + n), t);
    return v;
  }
  static std::string text(const std::string& s, std::size_t pos, std::size_t n) {
    std::string t = field(s, pos, n);
    while (!t.empty() && (t.back() == ' ' || t.back() == '\r')) t.pop_back();
    return t;
  }

  /// `count` numbers from data lines in the fixed `widths` (repeated along the line);
  /// a line whose blank-separated words are all numbers is read by its words.
  std::vector<double> numbers(std::size_t count, const std::vector<std::size_t>& widths, const std::string& record) {
    std::vector<double> out;
    out.reserve(count);
    while (out.size() < count) {
      const std::string& l = next(record + " (" + std::to_string(count - out.size()) + " more values)");
      std::vector<double> words;
      bool by_words = true;
      std::istringstream is(l);
      for (std::string w; is >> w;) {
        double v = 0;
        if (!parseReal(w, v)) {
          by_words = false;
          break;
        }
        words.push_back(v);
      }
      if (by_words && !words.empty()) {
        for (double v : words)
          if (out.size() < count) out.push_back(v);
        continue;
      }
      std::size_t pos = 0;
      for (std::size_t k = 0; out.size() < count && pos < l.size(); ++k) {
        const std::size_t w = widths[k % widths.size()];
        if (trimmed(field(l, pos, w)).empty()) break;
        out.push_back(real(l, pos, w, record + " value"));
        pos += w;
      }
    }
    return out;
  }

 private:
  std::vector<std::string> lines_;
  std::string source_, context_;
  std::size_t at_ = 0;
};

void read151(Cursor& c, File& file) {
  file.model_name = Cursor::text(c.next("record 1 (model name)"), 0, 80);
  file.description = Cursor::text(c.next("record 2 (description)"), 0, 80);
  file.program = Cursor::text(c.next("record 3 (program)"), 0, 80);
  if (!c.atClose()) {
    const std::string& d = c.next("record 4 (date)");
    file.date = Cursor::text(d, 0, 10);
    file.time = Cursor::text(d, 10, 10);
  }
}

void read164(Cursor& c, File& file) {
  const std::string& r1 = c.next("record 1 (units code)");
  file.units_description = trimmed(Cursor::field(r1, 10, 20));
  const std::vector<double> f = c.numbers(3, {25}, "record 2 (unit factors)");
  if (!(f[0] > 0) || !(f[1] > 0)) c.fail(0, "the length and force factors must be > 0", strf("%g %g", f[0], f[1]));
  file.length_factor = f[0];
  file.force_factor = f[1];
}

void readNodes15(Cursor& c, File& file) {
  while (!c.atClose()) {
    const std::string& l = c.next("a node");
    if (trimmed(l).empty()) continue;
    Node n;
    n.label = c.integer(l, 0, 10, "node label");
    // 3E13.5 by column; a line written with other widths is read by its words.
    std::istringstream is(l);
    std::vector<std::string> words;
    for (std::string w; is >> w;) words.push_back(w);
    double v[3];
    if (words.size() == 7 && parseReal(words[4], v[0]) && parseReal(words[5], v[1]) && parseReal(words[6], v[2])) {
      n.xyz = {v[0], v[1], v[2]};
    } else {
      n.xyz = {c.real(l, 40, 13, "node x"), c.real(l, 53, 13, "node y"), c.real(l, 66, 13, "node z")};
    }
    file.nodes.push_back(n);
  }
}

void readNodes2411(Cursor& c, File& file) {
  while (!c.atClose()) {
    const std::string& l = c.next("record 1 (node label)");
    if (trimmed(l).empty()) continue;
    Node n;
    n.label = c.integer(l, 0, 10, "node label");
    const std::vector<double> x = c.numbers(3, {25}, "record 2 (coordinates)");
    n.xyz = {x[0], x[1], x[2]};
    file.nodes.push_back(n);
  }
}

void read82(Cursor& c, File& file) {
  const std::string& h = c.next("record 1 (trace line number, nodes, colour)");
  TraceLine t;
  t.number = c.integer(h, 0, 10, "trace line number");
  const int n = c.integer(h, 10, 10, "number of nodes");
  if (n < 0 || n > 1000000) c.fail(10, "the number of nodes must be within 0..10^6", std::to_string(n));
  t.id = Cursor::text(c.next("record 2 (identification)"), 0, 80);
  while (static_cast<int>(t.nodes.size()) < n) {
    const std::string& l = c.next("record 3 (nodes)");
    for (int k = 0; k < 8 && static_cast<int>(t.nodes.size()) < n; ++k) t.nodes.push_back(c.integer(l, 10 * k, 10, "node"));
  }
  file.trace_lines.push_back(t);
}

void read55(Cursor& c, File& file) {
  for (int k = 1; k <= 5; ++k) c.next("record " + std::to_string(k) + " (ID line)");
  const std::string& r6 = c.next("record 6 (data definition)");
  const int analysis = c.integer(r6, 10, 10, "analysis type");
  const int characteristic = c.integer(r6, 20, 10, "data characteristic");
  const int data_type = c.integer(r6, 40, 10, "data type");
  const int ndv = c.integer(r6, 50, 10, "values per node");
  if (analysis != 2 && analysis != 3)
    c.fail(10, "analysis type must be 2 (normal modes) or 3 (complex eigenvalue modes): other data are not modes",
           std::to_string(analysis));
  if (!((characteristic == 2 && ndv == 3) || (characteristic == 3 && ndv == 6)))
    c.fail(20, "data characteristic and values per node must be 2 and 3 (translations) or 3 and 6 (with rotations)",
           std::to_string(characteristic) + " " + std::to_string(ndv));
  if (data_type != 2 && data_type != 5) c.fail(40, "data type must be 2 (real) or 5 (complex)", std::to_string(data_type));
  const bool complex_data = data_type == 5;
  const std::string& r7 = c.next("record 7 (integer parameters)");
  const int nint = c.integer(r7, 0, 10, "number of integer values");
  const int nreal = c.integer(r7, 10, 10, "number of real values");
  if (nint < 2 || nint > 8 || nreal < 1 || nreal > 12)
    c.fail(0, "record 7 must give 2-8 integer and 1-12 real values", std::to_string(nint) + " " + std::to_string(nreal));
  ModeShape m;
  m.line = c.lineNumber() - 7;
  m.mode = c.integer(r7, 30, 10, "mode number");
  const std::vector<double> r8 = c.numbers(static_cast<std::size_t>(nreal), {13}, "record 8 (real parameters)");
  if (analysis == 2) {
    m.frequency_hz = r8[0];
    m.modal_mass = nreal > 1 ? r8[1] : 0.0;
    m.damping_ratio = nreal > 2 ? r8[2] : 0.0;
  } else {  // complex eigenvalue lambda = sigma + i omega_d, rad/s
    if (nreal < 2) c.fail(0, "a complex mode's record 8 must give its eigenvalue (2 values)", std::to_string(nreal));
    const double mag = std::hypot(r8[0], r8[1]);
    m.frequency_hz = mag / (2 * M_PI);
    m.damping_ratio = mag > 0 ? -r8[0] / mag : 0.0;
  }
  if (!(m.frequency_hz >= 0)) c.fail(0, "a mode's frequency must be >= 0 Hz", strf("%g", m.frequency_hz));
  const std::size_t per_node = static_cast<std::size_t>(ndv) * (complex_data ? 2 : 1);
  while (!c.atClose()) {
    const std::string& r9 = c.next("record 9 (node number)");
    if (trimmed(r9).empty()) continue;
    const int node = c.integer(r9, 0, 10, "node number");
    const std::vector<double> v = c.numbers(per_node, {13}, "record 10 (data at node " + std::to_string(node) + ")");
    std::array<double, 3> re{}, im{};
    for (int d = 0; d < 3; ++d) {
      re[d] = complex_data ? v[2 * d] : v[d];
      im[d] = complex_data ? v[2 * d + 1] : 0.0;
    }
    m.nodes.push_back(node);
    m.translations.push_back(re);
    if (complex_data) m.translations_imag.push_back(im);
    if (ndv == 6 && !complex_data) m.rotations.push_back({v[3], v[4], v[5]});  // a complex mode's rotations are not kept
  }
  file.modes.push_back(m);
}

/// Record 6 and 7-11 of dataset 58 into `fn`; returns (ordinate data type, points, even, min, increment).
struct DataForm {
  int type = 0, points = 0;
  bool even = false;
  double min = 0, increment = 0;
};

DataForm read58Header(Cursor& c, Function& fn) {
  fn.id1 = Cursor::text(c.next("record 1 (ID line 1)"), 0, 80);
  fn.id2 = Cursor::text(c.next("record 2 (ID line 2)"), 0, 80);
  fn.id3 = Cursor::text(c.next("record 3 (ID line 3)"), 0, 80);
  fn.id4 = Cursor::text(c.next("record 4 (ID line 4)"), 0, 80);
  fn.id5 = Cursor::text(c.next("record 5 (ID line 5)"), 0, 80);
  const std::string& r6 = c.next("record 6 (DOF identification)");
  fn.function_type = c.integer(r6, 0, 5, "function type");
  fn.response_node = c.integer(r6, 41, 10, "response node");
  fn.response_direction = c.integer(r6, 51, 4, "response direction");
  fn.reference_node = c.integer(r6, 66, 10, "reference node");
  fn.reference_direction = c.integer(r6, 76, 4, "reference direction");
  if (std::abs(fn.response_direction) > 6) c.fail(51, "response direction must be within -6..6", std::to_string(fn.response_direction));
  if (std::abs(fn.reference_direction) > 6) c.fail(76, "reference direction must be within -6..6", std::to_string(fn.reference_direction));
  const std::string& r7 = c.next("record 7 (data form)");
  DataForm f;
  f.type = c.integer(r7, 0, 10, "ordinate data type");
  f.points = c.integer(r7, 10, 10, "number of points");
  const int spacing = c.integer(r7, 20, 10, "abscissa spacing");
  f.min = c.real(r7, 30, 13, "abscissa minimum");
  f.increment = c.real(r7, 43, 13, "abscissa increment");
  if (f.type != 2 && f.type != 4 && f.type != 5 && f.type != 6)
    c.fail(0, "ordinate data type must be 2 (real single), 4 (real double), 5 (complex single) or 6 (complex double)",
           std::to_string(f.type));
  if (f.points < 1 || f.points > 10000000) c.fail(10, "the number of points must be within 1..10^7", std::to_string(f.points));
  if (spacing != 0 && spacing != 1) c.fail(20, "abscissa spacing must be 0 (uneven) or 1 (even)", std::to_string(spacing));
  f.even = spacing == 1;
  if (f.even && !(f.increment > 0)) c.fail(43, "an even abscissa's increment must be > 0", strf("%g", f.increment));
  c.next("record 8 (abscissa)");
  const std::string& r9 = c.next("record 9 (ordinate numerator)");
  fn.ordinate_type = c.integer(r9, 0, 10, "ordinate specific data type");
  fn.ordinate_length_exp = c.integer(r9, 10, 5, "ordinate length exponent");
  fn.ordinate_force_exp = c.integer(r9, 15, 5, "ordinate force exponent");
  fn.ordinate_label = trimmed(Cursor::field(r9, 26, 20));
  fn.ordinate_units = trimmed(Cursor::field(r9, 47, 20));
  const std::string& r10 = c.next("record 10 (ordinate denominator)");
  fn.denominator_type = c.integer(r10, 0, 10, "denominator specific data type");
  fn.denominator_length_exp = c.integer(r10, 10, 5, "denominator length exponent");
  fn.denominator_force_exp = c.integer(r10, 15, 5, "denominator force exponent");
  fn.denominator_label = trimmed(Cursor::field(r10, 26, 20));
  fn.denominator_units = trimmed(Cursor::field(r10, 47, 20));
  c.next("record 11 (z axis)");
  return f;
}

void read58(Cursor& c, File& file) {
  Function fn;
  fn.line = c.lineNumber() - 1;
  const DataForm f = read58Header(c, fn);
  const bool complex_data = f.type == 5 || f.type == 6, dbl = f.type == 4 || f.type == 6;
  const std::size_t n = static_cast<std::size_t>(f.points);
  const std::size_t per_point = (complex_data ? 2 : 1) + (f.even ? 0 : 1);
  std::vector<std::size_t> widths;  // record 12's published layouts
  if (!dbl) widths = {13};                       // 6E13.5
  else if (f.even) widths = {20};                // 4E20.12
  else if (complex_data) widths = {13, 20, 20};  // E13.5, 2E20.12
  else widths = {13, 20};                        // 2(E13.5, E20.12)
  const std::vector<double> v = c.numbers(n * per_point, widths, "record 12 (data)");
  for (std::size_t i = 0; i < n; ++i) {
    const double* p = v.data() + i * per_point;
    const double x = f.even ? f.min + static_cast<double>(i) * f.increment : *p++;
    fn.frequency_hz.push_back(x);
    fn.values.emplace_back(p[0], complex_data ? p[1] : 0.0);
  }
  for (std::size_t i = 1; i < n; ++i)
    if (!(fn.frequency_hz[i] > fn.frequency_hz[i - 1]))
      c.fail(0, "the abscissa must increase (point " + std::to_string(i + 1) + ")",
             strf("%g after %g", fn.frequency_hz[i], fn.frequency_hz[i - 1]));
  if (fn.frequency_hz.front() < 0) c.fail(0, "frequencies must be >= 0 Hz", strf("%g", fn.frequency_hz.front()));
  file.functions.push_back(fn);
}

/// Every value in SI: coordinates and shapes divided by the length factor, functions
/// scaled by their numerator's and denominator's unit exponents.
void toSi(File& file) {
  const double L = file.length_factor, F = file.force_factor;
  if (L == 1 && F == 1) return;
  for (auto& n : file.nodes)
    for (double& x : n.xyz) x /= L;
  for (auto& m : file.modes) {
    for (auto& t : m.translations)
      for (double& x : t) x /= L;
    for (auto& t : m.translations_imag)
      for (double& x : t) x /= L;
  }
  for (auto& fn : file.functions) {
    const double s = std::pow(L, fn.denominator_length_exp - fn.ordinate_length_exp) *
                     std::pow(F, fn.denominator_force_exp - fn.ordinate_force_exp);
    for (auto& h : fn.values) h *= s;
  }
}

}  // namespace

File read(const std::string& text, const std::string& source) {
  Cursor c(text, source);
  File file;
  std::set<int> labels;
  while (!c.done()) {
    if (trimmed(c.peek()).empty()) {
      c.skip();
      continue;
    }
    c.setContext("");
    if (!isDelimiter(c.peek())) {
      const std::string got = c.peek();
      c.skip();
      c.fail(0, "expected -1 opening a dataset", got.substr(0, 40));
    }
    c.skip();
    const std::string& header = c.next("a dataset number");
    const int type = c.integer(header, 0, 6, "dataset number");
    if (Cursor::text(header, 6, 1) == "b")
      c.fail(6, "dataset " + std::to_string(type) + "b is binary; export the file as ASCII UFF", trimmed(header));
    c.setContext("dataset " + std::to_string(type) + ": ");
    const std::size_t nodes_before = file.nodes.size();
    switch (type) {
      case 151: read151(c, file); break;
      case 164: read164(c, file); break;
      case 15: readNodes15(c, file); break;
      case 2411: readNodes2411(c, file); break;
      case 82: read82(c, file); break;
      case 55: read55(c, file); break;
      case 58: read58(c, file); break;
      default: break;  // datasets we do not use: skipped to their -1
    }
    for (std::size_t i = nodes_before; i < file.nodes.size(); ++i)
      if (!labels.insert(file.nodes[i].label).second)
        c.fail(0, "node " + std::to_string(file.nodes[i].label) + " is defined twice");
    c.closeDataset();
  }
  toSi(file);
  return file;
}

}  // namespace mmv::uff

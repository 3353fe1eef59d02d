#include "sim/uff.hpp"

#include "sim/table.hpp"

#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace mmv::uff {
namespace {

/// An 80-column text field (A80), cut or padded.
std::string a80(const std::string& s) {
  std::string t = s.substr(0, 80);
  return t + std::string(80 - t.size(), ' ');
}
/// An n-column text field (nA1).
std::string an(const std::string& s, std::size_t n) {
  std::string t = s.substr(0, n);
  return t + std::string(n - t.size(), ' ');
}
/// FORTRAN D25.17: like E25.17 with the exponent letter D.
std::string d25(double v) {
  std::string s = strf("%25.17E", v);
  for (char& c : s)
    if (c == 'E') c = 'D';
  return s;
}

void begin(std::ostringstream& os, int type) { os << strf("%6d\n%6d%74s\n", -1, type, ""); }
void end(std::ostringstream& os) { os << strf("%6d\n", -1); }

}  // namespace

std::string write(const File& file) {
  std::ostringstream os;
  begin(os, 151);
  os << a80(file.model_name) << '\n' << a80(file.description) << '\n' << a80(file.program) << '\n';
  os << an(file.date, 10) << an(file.time, 10) << strf("%10d%10d%10d", 0, 0, 0) << '\n';
  os << an(file.date, 10) << an(file.time, 10) << '\n';
  os << a80(file.program) << '\n';
  os << an(file.date, 10) << an(file.time, 10) << '\n';
  end(os);

  begin(os, 164);  // SI: metre, newton, kelvin (absolute temperature mode 2)
  os << strf("%10d", 1) << an("SI: Meter (newton)", 20) << strf("%10d", 2) << '\n';
  os << d25(1.0) << d25(1.0) << d25(1.0) << '\n' << d25(273.15) << '\n';
  end(os);

  if (!file.nodes.empty()) {
    begin(os, 15);
    for (const auto& n : file.nodes)
      os << strf("%10d%10d%10d%10d%13.5E%13.5E%13.5E\n", n.label, 0, 0, 8, n.xyz[0], n.xyz[1], n.xyz[2]);
    end(os);
  }
  for (const auto& t : file.trace_lines) {
    begin(os, 82);
    os << strf("%10d%10zu%10d\n", t.number, t.nodes.size(), 8) << a80(t.id) << '\n';
    for (std::size_t i = 0; i < t.nodes.size(); ++i) os << strf("%10d", t.nodes[i]) << ((i % 8 == 7 || i + 1 == t.nodes.size()) ? "\n" : "");
    end(os);
  }
  for (const auto& m : file.modes) {
    begin(os, 55);
    os << a80("mode " + std::to_string(m.mode)) << '\n' << a80(file.model_name) << '\n' << a80("NONE") << '\n'
       << a80("NONE") << '\n' << a80("NONE") << '\n';
    // structural model, normal modes, 3 DOF global translation, displacement, real, 3 values
    os << strf("%10d%10d%10d%10d%10d%10d\n", 1, 2, 2, 8, 2, 3);
    os << strf("%10d%10d%10d%10d\n", 2, 4, 1, m.mode);
    os << strf("%13.5E%13.5E%13.5E%13.5E\n", m.frequency_hz, m.modal_mass, m.damping_ratio, 0.0);
    for (std::size_t i = 0; i < m.nodes.size(); ++i)
      os << strf("%10d\n%13.5E%13.5E%13.5E\n", m.nodes[i], m.translations[i][0], m.translations[i][1], m.translations[i][2]);
    end(os);
  }
  for (const auto& fn : file.functions) {
    begin(os, 58);
    os << a80(fn.id1) << '\n' << a80(fn.id2) << '\n' << a80(fn.id3) << '\n' << a80(fn.id4) << '\n' << a80(fn.id5) << '\n';
    os << strf("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", fn.function_type, 1, 0, 0, "NONE", fn.response_node,
            fn.response_direction, "NONE", fn.reference_node, fn.reference_direction);
    // complex double (6), uneven abscissa (0)
    os << strf("%10d%10zu%10d%13.5E%13.5E%13.5E\n", 6, fn.frequency_hz.size(), 0, 0.0, 0.0, 0.0);
    os << strf("%10d%5d%5d%5d ", 18, 0, 0, 0) << an("Frequency", 20) << ' ' << an("Hz", 20) << '\n';
    os << strf("%10d%5d%5d%5d ", fn.ordinate_type, fn.ordinate_length_exp, fn.ordinate_force_exp, 0)
       << an(fn.ordinate_label, 20) << ' ' << an(fn.ordinate_units, 20) << '\n';
    os << strf("%10d%5d%5d%5d ", fn.denominator_type, fn.denominator_length_exp, fn.denominator_force_exp, 0)
       << an(fn.denominator_label, 20) << ' ' << an(fn.denominator_units, 20) << '\n';
    os << strf("%10d%5d%5d%5d ", 0, 0, 0, 0) << an("NONE", 20) << ' ' << an("NONE", 20) << '\n';
    for (std::size_t i = 0; i < fn.frequency_hz.size(); ++i)  // 1E13.5, 2E20.12
      os << strf("%13.5E%20.12E%20.12E\n", fn.frequency_hz[i], fn.values[i].real(), fn.values[i].imag());
    end(os);
  }
  return os.str();
}

namespace {

struct Reader {
  std::vector<std::string> lines;
  std::size_t at = 0;
  std::string line(const char* what) {
    if (at >= lines.size()) throw std::runtime_error("UFF: file ends inside " + std::string(what));
    return lines[at++];
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("UFF line " + std::to_string(at) + ": " + what);
  }
  static std::string field(const std::string& s, std::size_t pos, std::size_t n) {
    return pos < s.size() ? s.substr(pos, n) : std::string();
  }
  int integer(const std::string& s, std::size_t pos, std::size_t n) {
    const std::string t = field(s, pos, n);
    char* e = nullptr;
    const long v = std::strtol(t.c_str(), &e, 10);
    if (e == t.c_str()) fail("expected an integer in columns " + std::to_string(pos + 1) + "-" + std::to_string(pos + n));
    return static_cast<int>(v);
  }
  double real(const std::string& s, std::size_t pos, std::size_t n) {
    std::string t = field(s, pos, n);
    for (char& c : t)
      if (c == 'D' || c == 'd') c = 'E';
    char* e = nullptr;
    const double v = std::strtod(t.c_str(), &e);
    if (e == t.c_str()) fail("expected a number in columns " + std::to_string(pos + 1) + "-" + std::to_string(pos + n));
    return v;
  }
  static std::string text(const std::string& s, std::size_t pos, std::size_t n) {
    std::string t = field(s, pos, n);
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t;
  }
};

}  // namespace

File read(const std::string& content) {
  Reader r;
  std::istringstream is(content);
  for (std::string l; std::getline(is, l);) r.lines.push_back(l);
  File file;
  while (r.at < r.lines.size()) {
    const std::string delim = r.line("a delimiter");
    if (delim.find_first_not_of(' ') == std::string::npos) continue;
    if (r.integer(delim, 0, 6) != -1) r.fail("expected -1 opening a dataset");
    const int type = r.integer(r.line("a dataset number"), 0, 6);
    auto isEnd = [&](const std::string& l) { return l.size() >= 6 && l.substr(0, 6) == "    -1"; };
    if (type == 151) {
      file.model_name = Reader::text(r.line("151"), 0, 80);
      file.description = Reader::text(r.line("151"), 0, 80);
      file.program = Reader::text(r.line("151"), 0, 80);
      const std::string d = r.line("151");
      file.date = Reader::text(d, 0, 10);
      file.time = Reader::text(d, 10, 10);
      for (int k = 0; k < 3; ++k) r.line("151");
    } else if (type == 15) {
      for (std::string l = r.line("15"); !isEnd(l); l = r.line("15"))
        file.nodes.push_back({r.integer(l, 0, 10), {r.real(l, 40, 13), r.real(l, 53, 13), r.real(l, 66, 13)}});
      continue;
    } else if (type == 82) {
      const std::string h = r.line("82");
      TraceLine t;
      t.number = r.integer(h, 0, 10);
      const int n = r.integer(h, 10, 10);
      t.id = Reader::text(r.line("82"), 0, 80);
      while (static_cast<int>(t.nodes.size()) < n) {
        const std::string l = r.line("82 nodes");
        for (int k = 0; k < 8 && static_cast<int>(t.nodes.size()) < n; ++k) t.nodes.push_back(r.integer(l, 10 * k, 10));
      }
      file.trace_lines.push_back(t);
    } else if (type == 55) {
      for (int k = 0; k < 5; ++k) r.line("55 id");
      const std::string p = r.line("55 record 6");
      if (r.integer(p, 10, 10) != 2 || r.integer(p, 50, 10) != 3) r.fail("only normal modes with 3 values per node are read");
      ModeShape m;
      m.mode = r.integer(r.line("55 record 7"), 30, 10);
      const std::string q = r.line("55 record 8");
      m.frequency_hz = r.real(q, 0, 13);
      m.modal_mass = r.real(q, 13, 13);
      m.damping_ratio = r.real(q, 26, 13);
      for (std::string l = r.line("55"); !isEnd(l); l = r.line("55")) {
        m.nodes.push_back(r.integer(l, 0, 10));
        const std::string v = r.line("55 values");
        m.translations.push_back({r.real(v, 0, 13), r.real(v, 13, 13), r.real(v, 26, 13)});
      }
      file.modes.push_back(m);
      continue;
    } else if (type == 58) {
      Function fn;
      fn.id1 = Reader::text(r.line("58"), 0, 80);
      fn.id2 = Reader::text(r.line("58"), 0, 80);
      fn.id3 = Reader::text(r.line("58"), 0, 80);
      fn.id4 = Reader::text(r.line("58"), 0, 80);
      fn.id5 = Reader::text(r.line("58"), 0, 80);
      const std::string r6 = r.line("58 record 6");
      fn.function_type = r.integer(r6, 0, 5);
      fn.response_node = r.integer(r6, 41, 10);
      fn.response_direction = r.integer(r6, 51, 4);
      fn.reference_node = r.integer(r6, 66, 10);
      fn.reference_direction = r.integer(r6, 76, 4);
      const std::string r7 = r.line("58 record 7");
      if (r.integer(r7, 0, 10) != 6 || r.integer(r7, 20, 10) != 0) r.fail("only complex double data over an uneven abscissa is read");
      const int n = r.integer(r7, 10, 10);
      r.line("58 record 8");
      const std::string r9 = r.line("58 record 9");
      fn.ordinate_type = r.integer(r9, 0, 10);
      fn.ordinate_length_exp = r.integer(r9, 10, 5);
      fn.ordinate_force_exp = r.integer(r9, 15, 5);
      fn.ordinate_label = Reader::text(r9, 26, 20);
      fn.ordinate_units = Reader::text(r9, 47, 20);
      const std::string r10 = r.line("58 record 10");
      fn.denominator_type = r.integer(r10, 0, 10);
      fn.denominator_length_exp = r.integer(r10, 10, 5);
      fn.denominator_force_exp = r.integer(r10, 15, 5);
      fn.denominator_label = Reader::text(r10, 26, 20);
      fn.denominator_units = Reader::text(r10, 47, 20);
      r.line("58 record 11");
      for (int i = 0; i < n; ++i) {
        const std::string v = r.line("58 data");
        fn.frequency_hz.push_back(r.real(v, 0, 13));
        fn.values.emplace_back(r.real(v, 13, 20), r.real(v, 33, 20));
      }
      file.functions.push_back(fn);
    }
    // Skip to the closing -1 (also skips datasets we do not read, such as 164).
    for (std::string l = r.line("a dataset"); !isEnd(l); l = r.line("a dataset")) {
    }
  }
  return file;
}

}  // namespace mmv::uff

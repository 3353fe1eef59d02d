#include "support/uff_reader.hpp"

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mmv::uff {
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

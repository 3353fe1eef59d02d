#include "sim/io/uff.hpp"

#include "sim/core/text.hpp"

#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <ctime>
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
    // structural model, normal modes, 3 DOF global translation (or 6 DOF global
    // translation and rotation), displacement, real, 3 (6) values per node
    const bool six = !m.rotations.empty();
    os << strf("%10d%10d%10d%10d%10d%10d\n", 1, 2, six ? 3 : 2, 8, 2, six ? 6 : 3);
    os << strf("%10d%10d%10d%10d\n", 2, 4, 1, m.mode);
    os << strf("%13.5E%13.5E%13.5E%13.5E\n", m.frequency_hz, m.modal_mass, m.damping_ratio, 0.0);
    for (std::size_t i = 0; i < m.nodes.size(); ++i) {
      os << strf("%10d\n%13.5E%13.5E%13.5E", m.nodes[i], m.translations[i][0], m.translations[i][1], m.translations[i][2]);
      if (six) os << strf("%13.5E%13.5E%13.5E", m.rotations[i][0], m.rotations[i][1], m.rotations[i][2]);
      os << '\n';
    }
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


void stampNow(File& file) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&now, &tm);
  char d[16], t[16];
  std::strftime(d, sizeof d, "%d-%b-%y", &tm);
  std::strftime(t, sizeof t, "%H:%M:%S", &tm);
  file.date = d;
  for (char& c : file.date) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  file.time = t;
}

}  // namespace mmv::uff

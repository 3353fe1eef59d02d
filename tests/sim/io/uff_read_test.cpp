// The UFF reader against files written by hand from the published record layouts
// (SDRC universal file format: datasets 15, 2411, 55, 58, 164), in the variants
// acquisition software emits: single and double precision, even and uneven abscissa,
// real and complex data, normal and complex modes, other units; and its messages on
// malformed files. The writer is not used here, so a shared misreading of a layout
// cannot pass.
#include "sim/io/uff_read.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <regex>

#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

namespace mmv {
namespace {

std::string e13(double v) { return strf("%13.5E", v); }
std::string e20(double v) { return strf("%20.12E", v); }
std::string i10(int v) { return strf("%10d", v); }
std::string line80(const std::string& s) { return s + std::string(80 - s.size(), ' '); }

/// Dataset 58's header (records 1-11) for `type` (2, 4, 5, 6), n points, even or not.
std::string header58(int type, int n, bool even, double min, double inc, int rsp_node, int rsp_dir, int ref_node,
                     int ref_dir) {
  std::string s = "    -1\n    58\n";
  for (const char* id : {"Accel / Force", "NONE", "NONE", "NONE", "NONE"}) s += line80(id) + "\n";
  // 2(I5,I10),2(1X,10A1,I10,I4)
  s += strf("%5d%10d%5d%10d %-10s%10d%4d %-10s%10d%4d\n", 4, 1, 0, 0, "NONE", rsp_node, rsp_dir, "NONE", ref_node, ref_dir);
  s += i10(type) + i10(n) + i10(even ? 1 : 0) + e13(min) + e13(inc) + e13(0.0) + "\n";  // 3I10,3E13.5
  s += strf("%10d%5d%5d%5d %-20s %-20s\n", 18, 0, 0, 0, "Frequency", "Hz");           // I10,3I5,2(1X,20A1)
  s += strf("%10d%5d%5d%5d %-20s %-20s\n", 12, 1, 0, 0, "Acceleration", "m/s^2");
  s += strf("%10d%5d%5d%5d %-20s %-20s\n", 13, 0, 1, 0, "Force", "N");
  s += strf("%10d%5d%5d%5d %-20s %-20s\n", 0, 0, 0, 0, "NONE", "NONE");
  return s;
}

/// A known FRF: one-DOF accelerance -w^2 / (k - m w^2 + i c w), values of both signs.
std::complex<double> known(double f) {
  const double w = 2 * M_PI * f, m = 2.0, k = 800.0, c = 1.5;
  return -w * w / std::complex<double>(k - m * w * w, c * w);
}

void expectKnown(const uff::Function& fn, const std::vector<double>& f, double rel) {
  ASSERT_EQ(fn.frequency_hz.size(), f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_NEAR(fn.frequency_hz[i], f[i], 1e-5 * f[i]);
    EXPECT_LE(std::abs(fn.values[i] - known(f[i])), rel * std::abs(known(f[i])) + 1e-300) << i;
  }
}

std::vector<double> grid(int n) {
  std::vector<double> f;
  for (int i = 0; i < n; ++i) f.push_back(1.0 + 0.5 * i);  // crosses the 3.18 Hz resonance
  return f;
}

TEST(UffRead, ComplexDoubleUnevenAbscissa) {  // E13.5, 2E20.12: a point per line
  const auto f = grid(7);
  std::string s = header58(6, 7, false, 0, 0, 3, 2, 1, 1);
  for (double x : f) s += e13(x) + e20(known(x).real()) + e20(known(x).imag()) + "\n";
  s += "    -1\n";
  const uff::File file = uff::read(s, "t.uff");
  ASSERT_EQ(file.functions.size(), 1u);
  expectKnown(file.functions[0], f, 1e-11);
  EXPECT_EQ(file.functions[0].response_node, 3);
  EXPECT_EQ(file.functions[0].response_direction, 2);
  EXPECT_EQ(file.functions[0].ordinate_type, 12);
  EXPECT_EQ(file.functions[0].denominator_type, 13);
}

TEST(UffRead, ComplexDoubleEvenAbscissa) {  // 4E20.12: two points per line
  const auto f = grid(7);
  std::string s = header58(6, 7, true, 1.0, 0.5, 3, 1, 1, 1);
  std::vector<double> v;
  for (double x : f) v.insert(v.end(), {known(x).real(), known(x).imag()});
  for (std::size_t i = 0; i < v.size(); ++i) s += e20(v[i]) + (i % 4 == 3 || i + 1 == v.size() ? "\n" : "");
  s += "    -1\n";
  expectKnown(uff::read(s, "t.uff").functions.at(0), f, 1e-11);
}

TEST(UffRead, ComplexSingleBothAbscissae) {  // 6E13.5: (x, re, im) pairs or (re, im) triples per line
  const auto f = grid(5);
  std::string uneven = header58(5, 5, false, 0, 0, 3, 1, 1, 1), even = header58(5, 5, true, 1.0, 0.5, 3, 1, 1, 1);
  std::vector<double> vu, ve;
  for (double x : f) {
    vu.insert(vu.end(), {x, known(x).real(), known(x).imag()});
    ve.insert(ve.end(), {known(x).real(), known(x).imag()});
  }
  for (std::size_t i = 0; i < vu.size(); ++i) uneven += e13(vu[i]) + (i % 6 == 5 || i + 1 == vu.size() ? "\n" : "");
  for (std::size_t i = 0; i < ve.size(); ++i) even += e13(ve[i]) + (i % 6 == 5 || i + 1 == ve.size() ? "\n" : "");
  expectKnown(uff::read(uneven + "    -1\n").functions.at(0), f, 1e-5);  // 6 significant digits
  expectKnown(uff::read(even + "    -1\n").functions.at(0), f, 1e-5);
}

TEST(UffRead, RealSingleAndDouble) {  // 6E13.5 even; 2(E13.5,E20.12) uneven: magnitudes as real data
  const auto f = grid(7);
  std::string single = header58(2, 7, true, 1.0, 0.5, 3, 1, 1, 1), dbl = header58(4, 7, false, 0, 0, 3, 1, 1, 1);
  for (std::size_t i = 0; i < f.size(); ++i) single += e13(-std::abs(known(f[i]))) + (i % 6 == 5 || i + 1 == f.size() ? "\n" : "");
  for (std::size_t i = 0; i < f.size(); ++i)
    dbl += e13(f[i]) + e20(-std::abs(known(f[i]))) + (i % 2 == 1 || i + 1 == f.size() ? "\n" : "");
  const auto a = uff::read(single + "    -1\n").functions.at(0), b = uff::read(dbl + "    -1\n").functions.at(0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_NEAR(a.values[i].real(), -std::abs(known(f[i])), 1e-5 * std::abs(known(f[i])));
    EXPECT_NEAR(b.values[i].real(), -std::abs(known(f[i])), 1e-11 * std::abs(known(f[i])));
    EXPECT_EQ(a.values[i].imag(), 0.0);
    EXPECT_NEAR(b.frequency_hz[i], f[i], 1e-9);
  }
}

TEST(UffRead, FieldsThatFillTheirColumnsAreReadByColumn) {
  // A writer that uses all 13 columns (E13.6): negative neighbours touch, "-1.0E+00-2.0E+00".
  const auto f = grid(6);
  std::string s = header58(2, 6, true, 1.0, 0.5, 3, 1, 1, 1);
  for (double x : f) s += strf("%13.6E", -std::abs(known(x)));
  s += "\n    -1\n";
  ASSERT_TRUE(std::regex_search(s, std::regex("E[+-][0-9][0-9]-[0-9]")));
  const auto fn = uff::read(s).functions.at(0);
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(fn.values[i].real(), -std::abs(known(f[i])), 1e-6 * std::abs(known(f[i])));
}

TEST(UffRead, ModesNormalComplexAndWithRotations) {
  std::string s = "    -1\n    55\n";
  for (int k = 0; k < 5; ++k) s += line80("NONE") + "\n";
  s += i10(1) + i10(2) + i10(3) + i10(8) + i10(2) + i10(6) + "\n";  // normal modes, 6 DOF, real
  s += i10(2) + i10(4) + i10(1) + i10(4) + "\n";
  s += e13(12.5) + e13(1.0) + e13(0.02) + e13(0.0) + "\n";
  s += i10(7) + "\n" + e13(0.1) + e13(-0.2) + e13(0.3) + e13(9.0) + e13(9.0) + e13(9.0) + "\n";
  s += "    -1\n    -1\n    55\n";
  for (int k = 0; k < 5; ++k) s += line80("NONE") + "\n";
  s += i10(1) + i10(3) + i10(2) + i10(8) + i10(5) + i10(3) + "\n";  // complex eigenvalue modes, 3 DOF, complex
  s += i10(2) + i10(6) + i10(1) + i10(2) + "\n";
  const double sigma = -0.05 * 2 * M_PI * 4.0, wd = 2 * M_PI * 4.0 * std::sqrt(1 - 0.0025);
  s += e13(sigma) + e13(wd) + e13(0.0) + e13(0.0) + e13(0.0) + e13(0.0) + "\n";
  s += i10(7) + "\n" + e13(1.0) + e13(0.5) + e13(-2.0) + e13(0.0) + e13(0.0) + e13(0.0) + "\n";
  s += "    -1\n";
  const uff::File file = uff::read(s);
  ASSERT_EQ(file.modes.size(), 2u);
  EXPECT_EQ(file.modes[0].mode, 4);
  EXPECT_NEAR(file.modes[0].frequency_hz, 12.5, 1e-9);
  EXPECT_NEAR(file.modes[0].damping_ratio, 0.02, 1e-9);
  EXPECT_NEAR(file.modes[0].translations[0][1], -0.2, 1e-9);
  ASSERT_EQ(file.modes[0].rotations.size(), 1u);  // the rotations kept
  EXPECT_NEAR(file.modes[0].rotations[0][2], 9.0, 1e-9);
  EXPECT_TRUE(file.modes[0].translations_imag.empty());
  EXPECT_NEAR(file.modes[1].frequency_hz, 4.0, 1e-4);
  EXPECT_NEAR(file.modes[1].damping_ratio, 0.05, 1e-5);
  EXPECT_NEAR(file.modes[1].translations[0][0], 1.0, 1e-9);
  EXPECT_NEAR(file.modes[1].translations_imag[0][0], 0.5, 1e-9);
  EXPECT_NEAR(file.modes[1].translations[0][1], -2.0, 1e-9);
}

TEST(UffRead, UnitsAndDoublePrecisionNodes) {  // 164 in mm and N; 2411 nodes (1P3D25.16)
  std::string s = "    -1\n   164\n" + strf("%10d%-20s%10d\n", 5, "mm (milli newton)", 2);
  s += strf("%25.17E%25.17E%25.17E\n", 1000.0, 1.0, 1.0) + strf("%25.17E\n", 273.15) + "    -1\n";
  std::string coords = strf("%25.16E%25.16E%25.16E\n", 1250.0, -2000.0, 0.0);
  for (char& c : coords)
    if (c == 'E') c = 'D';  // FORTRAN's D exponent in the double-precision node record
  s += "    -1\n  2411\n" + i10(5) + i10(0) + i10(0) + i10(1) + "\n" + coords + "    -1\n";
  s += header58(6, 2, false, 0, 0, 5, 1, 5, 1);  // acceleration (m^1) per force
  for (double x : {1.0, 2.0}) s += e13(x) + e20(1000.0) + e20(-500.0) + "\n";
  s += "    -1\n";
  const uff::File file = uff::read(s);
  ASSERT_EQ(file.nodes.size(), 1u);
  EXPECT_NEAR(file.nodes[0].xyz[0], 1.25, 1e-12);
  EXPECT_NEAR(file.nodes[0].xyz[1], -2.0, 1e-12);
  EXPECT_NEAR(file.functions[0].values[0].real(), 1.0, 1e-12);  // mm/s^2 per N -> m/s^2 per N
  EXPECT_NEAR(file.functions[0].values[0].imag(), -0.5, 1e-12);
}

/// The message of reading `s`, which must fail.
std::string failure(const std::string& s) {
  try {
    uff::read(s, "meas.uff");
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(UffRead, MalformedFilesAreNamedWithLineAndColumn) {
  std::string bad_type = header58(3, 2, false, 0, 0, 3, 1, 1, 1) + e13(1) + e13(1) + "\n    -1\n";
  EXPECT_NE(failure(bad_type).find("meas.uff:9:1: dataset 58: ordinate data type must be"), std::string::npos)
      << failure(bad_type);
  EXPECT_NE(failure(bad_type).find("(got '3')"), std::string::npos);
  std::string binary = "    -1\n    58b     1     1\n";
  EXPECT_NE(failure(binary).find("58b is binary"), std::string::npos) << failure(binary);
  std::string truncated = header58(6, 3, false, 0, 0, 3, 1, 1, 1) + e13(1.0) + e20(1) + e20(1) + "\n    -1\n";
  EXPECT_NE(failure(truncated).find("the dataset ends (-1) where record 12 (data)"), std::string::npos)
      << failure(truncated);
  std::string backwards = header58(6, 2, false, 0, 0, 3, 1, 1, 1) + e13(2.0) + e20(1) + e20(1) + "\n" + e13(1.0) +
                          e20(1) + e20(1) + "\n    -1\n";
  EXPECT_NE(failure(backwards).find("the abscissa must increase (point 2)"), std::string::npos) << failure(backwards);
  std::string unclosed = "    -1\n    15\n" + i10(1) + i10(0) + i10(0) + i10(8) + e13(0) + e13(0) + e13(0) + "\n";
  EXPECT_NE(failure(unclosed).find("the file ends"), std::string::npos) << failure(unclosed);
  std::string twice = "    -1\n    15\n" + i10(1) + i10(0) + i10(0) + i10(8) + e13(0) + e13(0) + e13(0) + "\n" + i10(1) +
                      i10(0) + i10(0) + i10(8) + e13(1) + e13(0) + e13(0) + "\n    -1\n";
  EXPECT_NE(failure(twice).find("node 1 is defined twice"), std::string::npos) << failure(twice);
  EXPECT_NE(failure("hello\n").find("meas.uff:1:1: expected -1 opening a dataset (got 'hello')"), std::string::npos)
      << failure("hello\n");
  std::string not_modes = "    -1\n    55\n";
  for (int k = 0; k < 5; ++k) not_modes += line80("NONE") + "\n";
  not_modes += i10(1) + i10(1) + i10(2) + i10(8) + i10(2) + i10(3) + "\n    -1\n";
  EXPECT_NE(failure(not_modes).find("analysis type must be 2 (normal modes) or 3"), std::string::npos) << failure(not_modes);
}

}  // namespace
}  // namespace mmv

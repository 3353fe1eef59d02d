#include "sim/io/uff.hpp"
#include "sim/io/uff_read.hpp"
#include "sim/core/errors.hpp"
#include "sim/core/text.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

namespace mmv {
namespace {

uff::File sample() {
  uff::File f;
  f.model_name = "MMV three-link flexible article";
  f.description = "round trip";
  f.date = "21-NOV-26";
  f.time = "11:30:00";
  f.nodes = {{1, {0.0, -0.0, 0.0}}, {2, {1.16236, -2.1451, 0}}, {17, {-3.5e-5, 12345.678, 0}}};
  f.trace_lines = {{1, "link1", {1, 2, 17, 2, 1, 0, 1, 2, 17}}};
  uff::ModeShape m;
  m.mode = 3;
  m.frequency_hz = 3.3403;
  m.modal_mass = 1.0;
  m.damping_ratio = 0.01;
  m.nodes = {1, 2, 17};
  m.translations = {{{0, 0, 0}}, {{-0.123456, 7.8e-9, 0}}, {{1e3, -2.5, 0}}};
  uff::ModeShape six = m;  // 6 DOF per node: the rotations too
  six.mode = 4;
  six.rotations = {{{0, 0, 1.5}}, {{-2e-3, 4.25, 0}}, {{0, -7.5e-8, 3}}};
  f.modes = {m, six};
  uff::Function fn;
  fn.function_type = 5;
  fn.id1 = "link3a.tip:x / table_x";
  fn.response_node = 17;
  fn.response_direction = 1;
  fn.reference_node = 1;
  fn.reference_direction = 1;
  fn.ordinate_label = "acceleration";
  fn.ordinate_units = "m/s^2";
  fn.denominator_label = "acceleration";
  fn.denominator_units = "m/s^2";
  for (int i = 0; i < 5; ++i) {
    fn.frequency_hz.push_back(0.01 * std::pow(10.0, i));
    fn.values.emplace_back(std::cos(i) * std::pow(10.0, i - 2), -std::sin(3.0 * i) * 1e-7);
  }
  f.functions = {fn};
  return f;
}

TEST(Uff, RoundTripOfEveryDataset) {
  const uff::File a = sample();
  const uff::File b = uff::read(uff::write(a));
  EXPECT_EQ(b.model_name, a.model_name);
  EXPECT_EQ(b.date, a.date);
  EXPECT_EQ(b.time, a.time);
  ASSERT_EQ(b.nodes.size(), a.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(b.nodes[i].label, a.nodes[i].label);
    for (int k = 0; k < 3; ++k)  // E13.5: 6 significant digits
      EXPECT_NEAR(b.nodes[i].xyz[k], a.nodes[i].xyz[k], 5e-6 * std::abs(a.nodes[i].xyz[k]) + 1e-300);
  }
  ASSERT_EQ(b.trace_lines.size(), 1u);
  EXPECT_EQ(b.trace_lines[0].nodes, a.trace_lines[0].nodes);
  EXPECT_EQ(b.trace_lines[0].id, "link1");
  ASSERT_EQ(b.modes.size(), 2u);
  EXPECT_EQ(b.modes[0].mode, 3);
  EXPECT_NEAR(b.modes[0].frequency_hz, 3.3403, 1e-9);
  EXPECT_TRUE(b.modes[0].rotations.empty());
  for (int n = 0; n < 2; ++n) {
    EXPECT_EQ(b.modes[n].nodes, a.modes[n].nodes);
    for (std::size_t i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(b.modes[n].translations[i][k], a.modes[n].translations[i][k],
                    5e-6 * std::abs(a.modes[n].translations[i][k]) + 1e-300);
  }
  ASSERT_EQ(b.modes[1].rotations.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(b.modes[1].rotations[i][k], a.modes[1].rotations[i][k], 5e-6 * std::abs(a.modes[1].rotations[i][k]) + 1e-300);
  ASSERT_EQ(b.functions.size(), 1u);
  const auto& fa = a.functions[0];
  const auto& fb = b.functions[0];
  EXPECT_EQ(fb.function_type, 5);
  EXPECT_EQ(fb.id1, fa.id1);
  EXPECT_EQ(fb.response_node, 17);
  EXPECT_EQ(fb.response_direction, 1);
  EXPECT_EQ(fb.reference_node, 1);
  EXPECT_EQ(fb.ordinate_type, 12);
  EXPECT_EQ(fb.ordinate_units, "m/s^2");
  ASSERT_EQ(fb.values.size(), fa.values.size());
  for (std::size_t i = 0; i < fa.values.size(); ++i) {
    EXPECT_NEAR(fb.frequency_hz[i], fa.frequency_hz[i], 5e-6 * fa.frequency_hz[i]);
    EXPECT_NEAR(std::abs(fb.values[i] - fa.values[i]), 0.0, 1e-12 * std::abs(fa.values[i]));  // E20.12
  }
}

// Every record against its FORTRAN format: the written line lengths and the fields at
// their columns (the reader above reads by column, so this checks the writer alone).
TEST(Uff, FixedWidthLayout) {
  std::istringstream is(uff::write(sample()));
  std::vector<std::string> l;
  for (std::string s; std::getline(is, s);) l.push_back(s);
  std::map<int, std::vector<std::size_t>> starts;  // dataset -> line index of its first record
  for (std::size_t i = 0; i + 1 < l.size(); ++i)
    if (l[i] == "    -1" && l[i + 1].size() == 80 && l[i + 1].substr(6).find_first_not_of(' ') == std::string::npos)
      starts[std::stoi(l[i + 1].substr(0, 6))].push_back(i + 2);
  for (int ds : {151, 164, 15, 82, 58}) ASSERT_EQ(starts.count(ds), 1u) << ds;
  ASSERT_EQ(starts.count(55), 1u);
  ASSERT_EQ(starts[55].size(), 2u);  // translations only, then 6 DOF
  for (const auto& s : l) EXPECT_LE(s.size(), 80u) << s;
  const std::size_t h = starts[151][0];
  for (int k : {0, 1, 2, 5}) EXPECT_EQ(l[h + k].size(), 80u);                 // 80A1
  EXPECT_EQ(l[h + 3].size(), 50u);                                           // 10A1,10A1,3I10
  EXPECT_EQ(l[h + 3].substr(0, 10), "21-NOV-26 ");
  const std::size_t u = starts[164][0];
  EXPECT_EQ(l[u].size(), 40u);                                               // I10,20A1,I10
  EXPECT_EQ(l[u + 1].size(), 75u);                                           // 3D25.17
  EXPECT_NE(l[u + 1].find("D+00"), std::string::npos);
  EXPECT_EQ(l[u + 2].size(), 25u);                                           // 1D25.17
  EXPECT_EQ(l[starts[15][0]].size(), 79u);                                   // 4I10,1P3E13.5
  EXPECT_EQ(l[starts[15][0] + 2].substr(0, 10), "        17");
  const std::size_t t = starts[82][0];
  EXPECT_EQ(l[t].size(), 30u);                                               // 3I10
  EXPECT_EQ(l[t + 1].size(), 80u);                                           // 80A1
  EXPECT_EQ(l[t + 2].size(), 80u);                                           // 8I10
  EXPECT_EQ(l[t + 3].size(), 10u);                                           // the ninth node
  const std::size_t m = starts[55][0];
  EXPECT_EQ(l[m + 5].size(), 60u);                                           // 6I10
  EXPECT_EQ(l[m + 5], "         1         2         2         8         2         3");
  EXPECT_EQ(l[m + 6].size(), 40u);                                           // 8I10 (4 used)
  EXPECT_EQ(l[m + 7].size(), 52u);                                           // 6E13.5 (4 used)
  EXPECT_EQ(l[m + 8].size(), 10u);                                           // I10 node
  EXPECT_EQ(l[m + 9].size(), 39u);                                           // 6E13.5 (3 used)
  const std::size_t six = starts[55][1];
  EXPECT_EQ(l[six + 5], "         1         2         3         8         2         6");  // 6 DOF global, 6 values
  EXPECT_EQ(l[six + 9].size(), 78u);                                         // 6E13.5
  const std::size_t f = starts[58][0];
  EXPECT_EQ(l[f + 5].size(), 80u);                                           // 2(I5,I10),2(1X,10A1,I10,I4)
  EXPECT_EQ(l[f + 5].substr(0, 5), "    5");                                 // function type: transmissibility
  EXPECT_EQ(l[f + 5].substr(41, 14), "        17   1");                      // response node and direction
  EXPECT_EQ(l[f + 6].size(), 69u);                                           // 3I10,3E13.5
  EXPECT_EQ(l[f + 6].substr(0, 30), "         6         5         0");     // complex double, 5 points, uneven
  for (int k = 7; k <= 10; ++k) EXPECT_EQ(l[f + k].size(), 67u);             // I10,3I5,2(1X,20A1)
  EXPECT_EQ(l[f + 7].substr(0, 10), "        18");                           // abscissa: frequency
  EXPECT_EQ(l[f + 8].substr(0, 10), "        12");                           // ordinate: acceleration
  EXPECT_EQ(l[f + 11].size(), 53u);                                          // E13.5,2E20.12
  EXPECT_EQ(l[f + 11].substr(13, 20).find('E'), 16u);                        // 12 decimals: " d.dddddddddddd" + E
}

TEST(Uff, MalformedRecordIsNamed) {
  std::string text = uff::write(sample());
  const auto at = text.find("    -1\n    15");
  ASSERT_NE(at, std::string::npos);
  text.replace(text.find('\n', at + 14) + 1, 10, "   garbage");
  try {
    uff::read(text);
    FAIL() << "expected an error";
  } catch (const SceneError& e) {
    // file:line:col, the dataset, the field and the value
    EXPECT_NE(std::string(e.what()).find("<uff>:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("dataset 15: node label must be an integer"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(got 'garbage"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace mmv

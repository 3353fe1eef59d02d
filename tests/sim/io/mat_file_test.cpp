#include "sim/io/mat_file.hpp"
#include "sim/io/mat5_writer.hpp"
#include "sim/core/errors.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace mmv {
namespace {

namespace fs = std::filesystem;

bool haveOctave() { return std::system("octave --version > /dev/null 2>&1") == 0; }

// The .mat file as an Octave user takes it: load it, sys = ss(A, B, C, D), and its
// frequency response at several frequencies equals ours, both Octave's freqresp and a
// direct solve C (i w I - A)^-1 B + D in Octave, to 1e-9 relative: the file holds the
// doubles exactly, and the solvers differ only by round-off.
TEST(MatFile, OctaveBuildsAWorkingSsObject) {
  if (!haveOctave()) GTEST_SKIP() << "octave is not installed (setup.sh installs it): .mat round trip NOT checked";
  ArticleScene s = loadDefaultScene();
  overrideSegments(s, 4);
  DampingSpec d;
  d.modal_ratio = 0.02;
  const LinearModel lm = buildLinearModel(s, defaultInputs(), defaultOutputs(s), d);
  ReductionOptions ro;
  ro.modes = 6;
  const ReducedModel red = reduceModal(lm.full, ro);
  const fs::path dir = fs::temp_directory_path() / ("mmvlab_mat_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path mat = dir / "rom.mat", result = dir / "h.txt";
  writeStateSpaceMat(mat.string(), red.model);
  const std::vector<double> hz{0.3, 1.3364, 3.3, 20.0};
  std::ostringstream w;
  w.precision(17);  // the frequencies must reach Octave exactly
  for (double f : hz) w << 2 * M_PI * f << ' ';
  const std::string script = "pkg load control; load('" + mat.string() +
                             "'); sys = ss(A, B, C, D); H = freqresp(sys, [" + w.str() +
                             "]); w = [" + w.str() + "]; Hd = zeros(size(H)); for k = 1:numel(w) Hd(:,:,k) = C * ((1i * w(k) * eye(rows(A)) - A) \\ B) + D; end; "
                             "f = fopen('" + result.string() +
                             "', 'w'); fprintf(f, '%d %d %d\\n', size(H)); fprintf(f, '%.17g %.17g %.17g %.17g\\n', [real(H(:)) imag(H(:)) real(Hd(:)) imag(Hd(:))]'); "
                             "fprintf(f, '%s\\n', InputName{1}, OutputName{1}, InputUnit{1}, OutputUnit{1}); fclose(f);";
  const std::string cmd = "octave --no-gui --quiet --no-window-system --eval \"" + script + "\" > /dev/null 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(result);
  int p = 0, m = 0, n = 0;
  in >> p >> m >> n;
  ASSERT_EQ(p, red.model.C.rows());
  ASSERT_EQ(m, red.model.B.cols());
  ASSERT_EQ(n, static_cast<int>(hz.size()));
  std::vector<std::complex<double>> h(p * m * n), hd(p * m * n);
  for (std::size_t k = 0; k < h.size(); ++k) {
    double re, im, red_, imd;
    in >> re >> im >> red_ >> imd;
    h[k] = {re, im};
    hd[k] = {red_, imd};
  }
  for (int k = 0; k < n; ++k) {
    const Eigen::MatrixXcd ours = red.model.standardForm().response(2 * M_PI * hz[k]);
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < p; ++i) {
        const std::size_t at = i + p * (j + m * k);  // column-major p x m x n
        const double scale = std::max(1.0, std::abs(ours(i, j)));
        EXPECT_LT(std::abs(hd[at] - ours(i, j)), 1e-9 * scale) << "direct, f " << hz[k] << " out " << i << " in " << j;
        EXPECT_LT(std::abs(h[at] - ours(i, j)), 1e-9 * scale) << "freqresp, f " << hz[k] << " out " << i << " in " << j;
      }
  }
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  while (std::getline(in, line)) names.push_back(line);
  ASSERT_EQ(names.size(), 4u);
  EXPECT_EQ(names[0], "table_x");
  EXPECT_EQ(names[1], red.model.output_names[0]);
  EXPECT_EQ(names[2], "m/s^2");
  fs::remove_all(dir);
}

// What writeMat writes, readMat reads back: every matrix to the bit, every string, in
// order; a file that is not there is a SceneFileError.
TEST(MatFile, WhatIsWrittenIsReadBack) {
  const fs::path dir = fs::temp_directory_path() / ("mmvlab_mat_roundtrip_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MatContents c;
  c.matrices.emplace_back("M", Eigen::MatrixXd::Random(4, 3));
  c.matrices.emplace_back("Empty", Eigen::MatrixXd(0, 3));
  c.matrices.emplace_back("Node", (Eigen::MatrixXd(2, 1) << 102440, 300762).finished());
  c.matrices.emplace_back("Four", Eigen::MatrixXd::Constant(1, 1, -0.0));  // a name at the small format's 4 bytes ...
  c.matrices.emplace_back("Fives", Eigen::MatrixXd::Constant(2, 2, 1e-300));  // ... and one past it
  c.strings.emplace_back("Channel", std::vector<std::string>{"link1@2.44m transverse", "", "link3a@0.762m axial"});
  // Beyond ASCII (written as UTF-16, read back as UTF-8): a Greek letter, a degree sign,
  // a code point past U+FFFF (a surrogate pair).
  c.strings.emplace_back("Unit", std::vector<std::string>{"\xcf\x89 (rad/s)", "\xc2\xb0", "\xf0\x9d\x9c\x94 tip", "x"});
  const std::string path = (dir / "t.mat").string();
  writeMat(path, c);
  const long size = static_cast<long>(fs::file_size(path));
  EXPECT_THROW(readMat(path, size - 1), SceneFileError);  // one byte past the bound
  const MatContents back = readMat(path, size);            // at it
  ASSERT_EQ(back.matrices.size(), c.matrices.size());
  for (std::size_t i = 0; i < c.matrices.size(); ++i) {
    EXPECT_EQ(back.matrices[i].first, c.matrices[i].first);
    ASSERT_EQ(back.matrices[i].second.rows(), c.matrices[i].second.rows());
    ASSERT_EQ(back.matrices[i].second.cols(), c.matrices[i].second.cols());
    EXPECT_TRUE(back.matrices[i].second == c.matrices[i].second) << c.matrices[i].first;
  }
  ASSERT_EQ(back.strings.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.strings[i].first, c.strings[i].first);
    EXPECT_EQ(back.strings[i].second, c.strings[i].second);
  }
  EXPECT_THROW(readMat((dir / "absent.mat").string(), size), SceneFileError);
  fs::remove_all(dir);
}

// The file's layout, read here without matio: the 128-byte header ends in version
// 0x0100 and 'IM'; the top-level elements are miMATRIX (14), each a multiple of 8 bytes,
// and they add up to the file; a matrix's data is its doubles, bit for bit.
TEST(MatFile, LayoutIsMat5) {
  const fs::path dir = fs::temp_directory_path() / ("mmvlab_mat_layout_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MatContents c;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(3, 5);
  c.matrices.emplace_back("A", A);
  c.strings.emplace_back("Names", std::vector<std::string>{"a", "bc"});
  const std::string path = (dir / "l.mat").string();
  writeMat(path, c);
  std::ifstream in(path, std::ios::binary);
  const std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(b.size(), 128u);
  EXPECT_EQ(b.substr(0, 10), "MATLAB 5.0");
  EXPECT_EQ(b[124], '\x00');
  EXPECT_EQ(b[125], '\x01');
  EXPECT_EQ(b.substr(126, 2), "IM");
  auto u32 = [&](std::size_t at) {
    std::uint32_t v;
    std::memcpy(&v, b.data() + at, 4);
    return v;
  };
  std::size_t at = 128;
  int elements = 0;
  while (at < b.size()) {
    EXPECT_EQ(u32(at), 14u) << "element " << elements;
    EXPECT_EQ(u32(at + 4) % 8, 0u) << "element " << elements;
    if (elements == 0) {  // flags (16), dims (16), name "A" (small, 8), then miDOUBLE
      EXPECT_EQ(u32(at + 8), 6u);
      EXPECT_EQ(u32(at + 16), 6u);  // mxDOUBLE_CLASS
      EXPECT_EQ(u32(at + 32), 3u);  // rows
      EXPECT_EQ(u32(at + 36), 5u);  // cols
      EXPECT_EQ(u32(at + 48), 9u);  // miDOUBLE
      EXPECT_EQ(u32(at + 52), 8u * 15);
      EXPECT_EQ(std::memcmp(b.data() + at + 56, A.data(), 8 * 15), 0);
    }
    at += 8 + u32(at + 4);
    ++elements;
  }
  EXPECT_EQ(at, b.size());
  EXPECT_EQ(elements, 2);
  fs::remove_all(dir);
}

// MAT 5's limits, enforced before a byte is written: a variable's byte count is 32
// bits (at the bound and one past it), a dimension 2^31 - 1 (an empty matrix of that many
// rows is written; one more row is refused, and no file is left).
TEST(MatFile, Mat5LimitsAreEnforced) {
  EXPECT_TRUE(mat5Fits(kMat5MaxElementBytes));
  EXPECT_FALSE(mat5Fits(kMat5MaxElementBytes + 1));
  const fs::path dir = fs::temp_directory_path() / ("mmvlab_mat_limits_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "x.mat").string();
  MatContents at_bound;
  at_bound.matrices.emplace_back("Tall", Eigen::MatrixXd(2147483647L, 0));
  writeMat(path, at_bound);
  EXPECT_EQ(readMat(path, 1 << 20).matrices.at(0).second.rows(), 2147483647L);
  fs::remove(path);
  MatContents past;
  past.matrices.emplace_back("Taller", Eigen::MatrixXd(2147483648L, 0));
  try {
    writeMat(path, past);
    ADD_FAILURE() << "a dimension past 2^31 - 1 was written";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("Taller"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(path));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mmv

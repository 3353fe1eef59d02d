#include "sim/io/mat_file.hpp"

#include <gtest/gtest.h>

#include <cstdio>
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
  c.strings.emplace_back("Channel", std::vector<std::string>{"link1@2.44m transverse", "", "link3a@0.762m axial"});
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
  ASSERT_EQ(back.strings.size(), 1u);
  EXPECT_EQ(back.strings[0].first, "Channel");
  EXPECT_EQ(back.strings[0].second, c.strings[0].second);
  EXPECT_THROW(readMat((dir / "absent.mat").string(), size), SceneFileError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace mmv

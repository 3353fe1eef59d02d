#pragma once
/// The .mat plugin's interface (sim/io/mat_file.hpp loads it). matio brings HDF5 and,
/// through it, curl, gnutls, Kerberos and ssh: about 30 shared libraries a command
/// reading no .mat file should not load (26 ms of a process on this machine), so matio
/// lives in libmmvlab_mat.so, loaded on the first .mat read; mmvlab writes .mat files
/// itself (sim/io/mat5_writer.hpp). No exception crosses the
/// boundary: each call returns its failure, and the loader throws mmvlab's own error.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

namespace mmv {

/// What a .mat file holds: named double matrices and named cell arrays of strings.
struct MatContents {
  std::vector<std::pair<std::string, Eigen::MatrixXd>> matrices;
  std::vector<std::pair<std::string, std::vector<std::string>>> strings;
};

/// A call's outcome: kind 0 done; 1 an output failure (OutputError); 2 a file that does
/// not open (SceneFileError); 3 a variable of a kind mmvlab does not read (SceneError).
struct MatStatus {
  int kind = 0;
  std::string message;
};

struct MatApi {
  int version;
  MatStatus (*read)(const std::string& path, MatContents& contents);
};

/// 2: read only (mmvlab writes MAT 5 itself, sim/io/mat5_writer.hpp).
inline constexpr int kMatApiVersion = 2;

}  // namespace mmv

#pragma once
/// MATLAB/Octave .mat (version 5) files: written by mmvlab itself (sim/io/mat5_writer.hpp:
/// one checked write of headers and the matrices' own data), read through matio in
/// libmmvlab_mat.so, loaded on the first read (sim/io/mat_plugin.hpp: matio's HDF5
/// brings a network stack no other command needs). The state-space export:
/// double matrices A, B, C, D, E (E = I: A and B are in standard form, so
/// `sys = ss(A, B, C, D)` works directly), the descriptor form as Ed, Ad, Bd, and cell
/// arrays InputName, OutputName, StateName, InputUnit, OutputUnit.

#include <string>
#include <utility>
#include <vector>

#include "sim/io/mat_plugin.hpp"
#include "sim/linear/state_space.hpp"

namespace mmv {

/// Writes `path` (MAT 5), every write, the flush to the disk and the close checked
/// (writeFileChecked); throws OutputError (a full disk, a variable past MAT 5's sizes).
void writeMat(const std::string& path, const MatContents& contents);

/// Reads `path`: every double matrix and every cell array of strings in it. Throws
/// SceneFileError when it does not open or is larger than `max_bytes`, SceneError when a
/// variable is neither.
MatContents readMat(const std::string& path, long max_bytes);

/// Writes `path`; throws OutputError if it cannot be written.
void writeStateSpaceMat(const std::string& path, const StateSpace& descriptor);

/// A reduced model and its full model, as writeStateSpaceMat writes each: the full
/// model's standard form (an n^3 solve) is made on another core while the reduced one
/// is written.
void writeStateSpaceMats(const std::string& reduced_path, const StateSpace& reduced, const std::string& full_path,
                         const StateSpace& full);

}  // namespace mmv

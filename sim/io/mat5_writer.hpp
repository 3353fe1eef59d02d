#pragma once
/// MAT 5 files (MATLAB's Level 5 MAT-file format, as MathWorks' "MAT-File Format"
/// describes it) written by mmvlab itself: uncompressed, little-endian, real double
/// matrices and cell arrays of character strings, laid out as matio 1.5 lays them out
/// (names of up to 4 bytes in the small element format, char data as miUTF8; a string
/// beyond ASCII as miUTF16, whose length MATLAB counts in UTF-16 units). The file is the
/// bytes of mat5Pieces in order: headers built here, each matrix's doubles taken from
/// the matrix itself (no copy of the 2 MB matrices of a 512-state model). matio (the
/// .mat plugin) reads them: tests/sim/io/mat_file_test.cpp reads every kind back through
/// it and through Octave.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sim/io/mat_plugin.hpp"

namespace mmv {

/// The largest data element MAT 5 can hold: its byte count is a 32-bit field.
inline constexpr std::uint64_t kMat5MaxElementBytes = 0xffffffffull;

/// The file's bytes as pieces: `storage` holds the headers (kept alive by the caller
/// while the pieces are written), the matrices' data is referenced in place (they must
/// outlive the write). Throws OutputError for a variable beyond MAT 5's 32-bit sizes
/// (a matrix of more than 2^32 - 1 bytes with its headers, or a dimension past 2^31 - 1),
/// naming it, before any byte is written.
std::vector<std::string_view> mat5Pieces(const MatContents& contents, std::string& storage);

/// Whether a variable of `bytes` (its miMATRIX element's contents) fits MAT 5's 32-bit
/// byte count.
bool mat5Fits(std::uint64_t bytes);

}  // namespace mmv

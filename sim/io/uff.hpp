#pragma once
/// Universal File Format (ASCII) export for test-analysis tools (SDRC record formats,
/// fixed-width FORTRAN fields): 151 header, 164 units (SI), 15 nodes, 82 trace lines,
/// 55 mode shapes (normal modes, 3 translations per node, or 6 DOF with the rotations), 58 functions (FRF, function
/// type 4, or transmissibility, type 5; complex double ordinate over an uneven
/// frequency abscissa). (sim/io/uff_read.hpp reads them, and what acquisition software writes.)

#include <array>
#include <complex>
#include <string>
#include <vector>

namespace mmv::uff {

struct Node {
  int label = 0;
  std::array<double, 3> xyz{};  ///< m.
};

struct TraceLine {
  int number = 0;
  std::string id;
  std::vector<int> nodes;  ///< 0 = pen up.
};

struct ModeShape {
  int mode = 0;
  double frequency_hz = 0, modal_mass = 0, damping_ratio = 0;
  std::vector<int> nodes;
  std::vector<std::array<double, 3>> translations;  ///< per node, m per unit modal coordinate.
  /// Per node, rad per unit modal coordinate about x, y, z (6 DOF per node: data
  /// characteristic 3); empty: translations only (characteristic 2).
  std::vector<std::array<double, 3>> rotations;
  /// Complex modes (read from analysis type 3 or complex data): the imaginary parts,
  /// per node; empty for a real (normal) mode.
  std::vector<std::array<double, 3>> translations_imag;
  int line = 0;  ///< read: the dataset's first line in its file (for messages).
};

struct Function {
  int function_type = 4;  ///< 4: frequency response function, 5: transmissibility.
  std::string id1, id2, id3, id4, id5;
  int response_node = 0, response_direction = 0;    ///< directions: 1 +X, 2 +Y, 3 +Z, 4..6 rotations.
  int reference_node = 0, reference_direction = 0;
  int ordinate_type = 12;      ///< specific data type: 8 displacement, 11 velocity, 12 acceleration.
  int ordinate_length_exp = 1, ordinate_force_exp = 0;
  std::string ordinate_label, ordinate_units;
  int denominator_type = 12;   ///< 12 acceleration, 13 excitation force.
  int denominator_length_exp = 1, denominator_force_exp = 0;
  std::string denominator_label, denominator_units;
  std::vector<double> frequency_hz;
  std::vector<std::complex<double>> values;
  int line = 0;  ///< read: the dataset's first line in its file (for messages).
};

struct File {
  std::string model_name, description, program = "mmvlab";
  std::string date = "01-JAN-70", time = "00:00:00";  ///< DD-MMM-YY, HH:MM:SS.
  std::vector<Node> nodes;
  std::vector<TraceLine> trace_lines;
  std::vector<ModeShape> modes;
  std::vector<Function> functions;
  /// Read: dataset 164's factors from the file's units to SI (SI value = file value /
  /// factor); 1 when the file has none. Values returned by read() are already in SI.
  double length_factor = 1, force_factor = 1;
  std::string units_description;
};

std::string write(const File& f);
/// The file's date and time fields: now (UTC), as DD-MMM-YY and HH:MM:SS.
void stampNow(File& f);

}  // namespace mmv::uff

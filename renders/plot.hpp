#pragma once
/// PNG figures drawn with OpenCV (no display needed): a heat map for MAC matrices and
/// x-y line plots for frequency maps. Plain data in, a file out; throws
/// std::runtime_error if the file cannot be written.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace mmv::render {

/// A heat map of `values` on a fixed [vmin, vmax] colour scale (MAC: 0..1), with each
/// cell's value printed in it, row and column labels, a title and a colour bar.
void writeHeatmapPng(const std::string& path, const Eigen::MatrixXd& values, const std::vector<std::string>& row_labels,
                     const std::vector<std::string>& col_labels, const std::string& title, const std::string& row_axis,
                     const std::string& col_axis, double vmin = 0.0, double vmax = 1.0);

struct Series {
  std::string label;
  std::vector<double> x = {}, y = {};  ///< equal lengths; non-finite points break the line.
  bool dashed = false;
  bool markers_only = false;  ///< points without connecting lines.
  int colour_index = -1;      ///< >= 0: a fixed colour of the palette (the same series the same colour in every figure).
  bool hollow = false;        ///< markers as rings (e.g. points that failed a check), drawn over filled ones.
  std::vector<std::string> point_labels = {};  ///< optional, one per point: a small label beside its marker.
};

/// A solid polyline's pixels with each pixel column's run of points reduced to its
/// first, lowest, highest and last, in their order (nullopt breaks the line): what
/// writeLinePlotPng draws, so a 10^5-sample time run costs a few thousand segments and
/// keeps its envelope.
struct Pixel {
  int x = 0, y = 0;
  bool operator==(const Pixel& o) const { return x == o.x && y == o.y; }
};
std::vector<std::optional<Pixel>> columnEnvelope(const std::vector<std::optional<Pixel>>& pts);

/// Line plot of several series with axes, ticks, labels and a legend.
void writeLinePlotPng(const std::string& path, const std::vector<Series>& series, const std::string& title,
                      const std::string& x_label, const std::string& y_label, bool log_y = false, bool log_x = false);

struct BodeTrace {
  std::string label;
  std::vector<double> frequency = {};     ///< Hz (or rad/s, see x_label), > 0.
  std::vector<double> magnitude_db = {};
  std::vector<double> phase_deg = {};
  bool dashed = false;
};

/// Bode plot: magnitude (dB) above phase (deg, unwrapped as MATLAB's bode draws it:
/// no +-360 deg jumps), both over log frequency, with a legend; `markers` (same unit as
/// the frequencies): the model's modes, dotted lines numbered from 1.
void writeBodePng(const std::string& path, const std::vector<BodeTrace>& traces, const std::string& title,
                  const std::string& x_label, const std::vector<double>& markers = {});

/// `phase` (deg) with the +-360 deg jumps between neighbouring points removed.
std::vector<double> unwrapPhaseDeg(std::vector<double> phase);

}  // namespace mmv::render

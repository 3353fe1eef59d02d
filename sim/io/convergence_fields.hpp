#pragma once
/// Field lists of a discretization ladder (sim/modes/converge.hpp): a mode's record over
/// the ladder (converge.json's modes, the discretization estimate of `modes`) and a
/// mode at one run (converge.csv's rows, Python's ConvergeResult.table()).

#include <cstddef>
#include <string>
#include <vector>

#include "sim/io/fields.hpp"
#include "sim/modes/converge.hpp"

namespace mmv {

/// A mode over the ladder: number, frequency_hz_by_run (JSON only), richardson_hz,
/// estimated_relative_error, observed_order, check ("unchecked" without an estimate).
const std::vector<Field<ConvergenceMode>>& convergenceModeFields();

/// One mode at one run of a convergence study.
struct ConvergencePoint {
  const ConvergenceMode* mode = nullptr;
  const ConvergenceRun* run = nullptr;
  std::size_t k = 0;  ///< the run's index
};
/// Its fields: mode, segments, dofs, frequency_hz, relative_error (against the
/// Richardson value), and the mode's richardson_hz, observed_order and check (its record's).
const std::vector<Field<ConvergencePoint>>& convergencePointFields();
/// The points that have a frequency (a run lacking a mode has no point), mode by mode.
std::vector<ConvergencePoint> convergencePoints(const ConvergenceStudy& c);

/// converge.csv: a row per point, a column per convergencePointFields() field.
std::string convergenceCsv(const ConvergenceStudy& c);

}  // namespace mmv

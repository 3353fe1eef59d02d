#pragma once
/// Reading Universal File Format (ASCII) files as modal acquisition and test-analysis
/// software writes them, for `mmvlab correlate`: measured FRFs (58), mode shapes (55)
/// and the geometry they refer to (15, 2411), in the units of 164.
///
/// Datasets read (others, such as 2412 elements, are skipped to their closing -1):
///  - 151 header: model name, description, program;
///  - 164 units: the factors from the file's units to SI (length, force); every
///    coordinate, shape and function is returned in SI (a value is divided by its
///    factor, as the format defines);
///  - 15 nodes (4I10, 3E13.5) and 2411 nodes (4I10 / 3D25.16); 82 trace lines;
///  - 55 data at nodes: normal modes (analysis type 2: frequency, modal mass, viscous
///    damping ratio) and complex modes (type 3: the eigenvalue, whose frequency and
///    damping ratio are derived), real or complex data, 3 or 6 values per node
///    (translations first; rotations are read and dropped);
///  - 58 function at nodal DOF, ASCII: real or complex, single or double precision
///    (ordinate data types 2, 4, 5, 6), even abscissa (from its minimum and increment)
///    or uneven (a value per point), in the published record-12 layouts
///    (6E13.5 / 4E20.12 / 2(E13.5,E20.12) / E13.5,2E20.12). Fields are read by column
///    as the format defines them; a data line whose values are separated by blanks is
///    read by its blanks, so files written with wider fields are read too. The binary
///    variant 58b is refused by name.
///
/// Errors are SceneError (exit 65) naming "file:line:col", the dataset and record, the
/// field and the value found: `meas.uff:212:1: dataset 58 record 7: ordinate data
/// type must be 2, 4, 5 or 6 (got 3)`.

#include <string>

#include "sim/io/uff.hpp"

namespace mmv::uff {

/// Parses `text` (the contents of `source`, named in messages). Node labels must be
/// unique; a 55 or 58 dataset naming a node no 15/2411 dataset defines is kept (the
/// caller decides), a function with no points or a non-increasing abscissa is an error.
File read(const std::string& text, const std::string& source = "<uff>");

}  // namespace mmv::uff

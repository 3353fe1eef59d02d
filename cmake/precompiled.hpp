// Precompiled headers (CMakeLists.txt, MMVLAB_PCH): the third-party headers that most
// of mmvlab's translation units include, directly or through sim/model/model.hpp,
// parsed once per build instead of once per file. Parsing Simbody.h alone costs about
// 3 s a file; the library and the tests hold about 150 files that include it.
//
// Only headers every user includes unchanged belong here: a file that defines a macro
// before including one of them (EIGEN_*) would see it ignored. Nothing of mmvlab's own.
#pragma once
#include <Simbody.h>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

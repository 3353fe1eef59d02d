#pragma once
/// The facility programs (plain data, facility/) a scene's motion specs stand for:
/// table and ground motion, commanded joint torques, torquer slews. Built when the
/// scene is read, so a program the facility refuses is an error at its key.

#include <memory>
#include <string>
#include <vector>

#include "facility/slews.hpp"
#include "facility/table_programs.hpp"
#include "sim/scene/scene.hpp"

namespace mmv {

/// The program for a motion spec. Throws std::invalid_argument (a bad CSV profile).
std::shared_ptr<const facility::TableProgram> makeTableProgram(const TableMotion& m);

/// The slew of a joint from `from` (rad) as `spec` commands (a move, a spin-up or an
/// angle program), within +-range (rad) unless the joint is continuous. Throws
/// std::invalid_argument when an angle lies outside the range, or a spin-up is asked
/// of a joint with a finite range.
facility::Slew makeSlew(const SlewSpec& spec, double from, double range, bool continuous);

/// When each slew of the article runs (joints, then the gimbal's axes): the axis, its
/// group ("torquers", "gimbal"), start and end (s; a spin-up's end is its ramp's).
struct SlewTiming {
  std::string axis, group;
  double start_s = 0, end_s = 0;
};
std::vector<SlewTiming> slewTimings(const ArticleSpec& article);
/// What a run of `duration` s shows of a slew: empty when the whole of it, else why not
/// ("it starts at ... at or after the run's end ..." or "... past the run's end ...").
std::string slewOutsideRun(const SlewTiming& t, double duration);

}  // namespace mmv

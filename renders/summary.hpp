#pragma once
/// A one-page summary image: a review's figures, already written as PNG files, laid out
/// on one canvas under a title, with the verdicts as lines of text (place-sensors'
/// summary.png: the chosen sensors on the article, the AutoMAC, the target modes with the
/// sensors' numbers, and the numbers a test-readiness review reads first).

#include <string>
#include <vector>

namespace mmv::render {

/// Writes `path`: `title` in a band across the top; `images[0]` large on the left,
/// `images[2]` (if any) under it, `images[1]` (if any) on the right with `lines` under
/// it, each line wrapped to the column. The images are read back from their files and
/// scaled (never enlarged). Throws std::runtime_error for an image that cannot be read.
void writeSummaryPng(const std::string& path, const std::string& title, const std::vector<std::string>& images,
                     const std::vector<std::string>& lines);

}  // namespace mmv::render

#pragma once
// What mmvlab report's pages share (sim/cli/report_command.cpp: the article's page;
// sim/cli/report_hamsas.cpp: the isolator's): the commands that reproduce a part, the
// figures drawn into --out's scratch space and inlined, tiles, the scene's part.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/cli/commands.hpp"
#include "sim/core/drawing.hpp"
#include "sim/core/files.hpp"
#include "sim/io/html_page.hpp"
#include "sim/io/output_dir.hpp"

namespace mmv::cli {

/// The page of a HAM-SAS scene into `out` (committed here): renders, modes with the
/// measured features, the sensor plan, the transmissibility against its goal, the scene.
int runHamsasReport(const ReportArgs& args, const HamsasScene& scene, OutputDir& out);

namespace report {

using Json = nlohmann::ordered_json;

/// A word of a shell command line, quoted when the shell would split or expand it.
std::string shellWord(const std::string& w);
/// "mmvlab VERB [SCENE] [scene options] EXTRA": the command that reproduces a part.
std::string commandFor(const ReportArgs& a, const std::string& verb, const std::string& extra);
/// A summary tile: its verdict class, the big line and the small one.
std::string tile(const std::string& cls, const std::string& big, const std::string& small);
/// The scene as read and the overrides the report ran with.
html::Section sceneSection(const ReportArgs& a, const std::string& text);

/// Writes report.html (the page) and report.json (`doc`, checked finite first) into
/// `out` (the directory `dir`) and commits them; returns the line that says where the
/// page is and its size.
std::string writeReport(OutputDir& out, const std::string& dir, const html::Page& page, const Json& doc);

class Embedder;
/// A 1280 x 720 figure per view (PREFIX_VIEW.png) of what `draw(view)` draws, in a grid
/// in `s`'s body, each captioned by `caption` (a printf format of the view's name) with
/// the render command that reproduces it.
void addViewFigures(html::Section& s, const ReportArgs& a, Embedder& em, const std::vector<std::string>& views,
                    const std::string& prefix, const std::function<DrawList(const std::string& view)>& draw,
                    const std::string& caption);
/// modes.png: modes 1 to n, `tile(mode)` each, as a contact sheet from `view`; the
/// caption says they are drawn about `about`.
std::string modesSheetFigure(Embedder& em, const std::string& view, int n, const std::function<DrawList(int mode)>& tile,
                             const std::string& about);

/// The figures the page embeds: each drawn into the output's scratch space, read back
/// and inlined; `count` of them so far.
class Embedder {
 public:
  explicit Embedder(OutputDir& out) : out_(out) {}
  /// Draws with `draw(path)` and returns the <figure>.
  std::string figure(const std::string& name, const std::function<void(const std::string&)>& draw, const std::string& alt,
                     const std::string& caption) {
    const std::string path = out_.scratch(name);
    try {
      draw(path);
    } catch (const std::runtime_error& e) {
      throw OutputError(e.what());
    }
    return html::pngFigure(read(path), alt, caption);
  }
  /// The figures `write(at)` draws, through `at`, each inlined with `caption(name)`.
  std::string figures(const std::function<void(const FigurePath&)>& write,
                      const std::function<std::string(const std::string&)>& caption) {
    std::vector<std::pair<std::string, std::string>> drawn;
    write([&](const std::string& name) {
      drawn.emplace_back(name, out_.scratch(name));
      return drawn.back().second;
    });
    std::string html;
    for (const auto& [name, path] : drawn) html += html::pngFigure(read(path), name, caption(name));
    return html;
  }
  int count() const { return count_; }

 private:
  std::string read(const std::string& path) {
    std::string bytes, why;
    if (!readInputFile(path, 64L << 20, bytes, why) || bytes.empty())
      throw OutputError(path + ": the figure was not written: " + (why.empty() ? "empty file" : why));
    static const std::string kPngEnd("IEND\xAE\x42\x60\x82", 8);  // a PNG's last chunk: the file is whole
    if (bytes.size() < 16 || bytes.compare(0, 4, "\x89PNG") != 0 || bytes.compare(bytes.size() - 8, 8, kPngEnd) != 0)
      throw OutputError(path + ": the figure is not a whole PNG (" + std::to_string(bytes.size()) + " bytes)");
    ++count_;
    return bytes;
  }
  OutputDir& out_;
  int count_ = 0;
};

}  // namespace report
}  // namespace mmv::cli

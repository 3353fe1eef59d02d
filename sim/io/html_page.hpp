#pragma once
/// One self-contained HTML page (`mmvlab report`): inline style, figures as data: URIs,
/// no script, and a Content-Security-Policy that lets the browser load nothing else, so
/// the page opens the same from a laptop, an e-mail or an air-gapped lab machine and
/// prints to PDF from the browser (A4, a section never split from its heading).

#include <string>
#include <string_view>
#include <vector>

namespace mmv::html {

/// `text` with & < > " ' as entities (safe in element content and quoted attributes).
std::string escape(std::string_view text);

/// RFC 4648 base64 (with padding) of `bytes`.
std::string base64(std::string_view bytes);

/// A figure: the PNG `png` as a data: URI with `alt` text, and its caption (text). One at
/// least 1600 pixels wide (a contact sheet) takes a whole row of a grid.
std::string pngFigure(std::string_view png, const std::string& alt, const std::string& caption);

/// A table of text cells (escaped here). A column whose cells all read as numbers ("-"
/// and empty cells aside) is right-aligned; a row may carry a CSS class (`pass`, `warn`,
/// `fail`, `info`, `na`) that colours it.
struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> row_classes;  ///< empty, or one per row ("" for none)
};
std::string table(const Table& t);

/// One part of the page: `body` is HTML (built with the functions above); `accuracy`
/// and `commands` are text, shown under it ("How accurate" and "Reproduce").
struct Section {
  std::string id, title, body;
  std::vector<std::string> accuracy;
  std::vector<std::string> commands;
};

struct Page {
  std::string title;          ///< text: the page's title and heading
  std::string subtitle;       ///< text: under the heading
  std::string summary;        ///< HTML: the verdicts at a glance, before the contents
  std::vector<Section> sections;
  std::string footer;         ///< text
};

/// The whole page: doctype, head (charset, CSP, style), the heading, the summary, a
/// table of contents linking the sections, the sections, the footer.
std::string page(const Page& p);

}  // namespace mmv::html

#include "sim/io/html_page.hpp"


namespace mmv::html {
namespace {

// Print: A4 with 14 mm margins; the contents list is for the screen; a figure or a table
// row is never cut across pages; a section's heading stays with what follows it.
constexpr const char* kStyle = R"css(
:root { --ink: #1d2329; --muted: #5b6670; --rule: #d5dae0; --band: #f4f6f8; --accent: #1f5fa8; }
* { box-sizing: border-box; }
body { margin: 0 auto; max-width: 1180px; padding: 24px 32px 48px; color: var(--ink);
  font: 15px/1.45 "DejaVu Sans", "Liberation Sans", Arial, sans-serif; background: #fff; }
h1 { font-size: 26px; margin: 0 0 4px; }
h2 { font-size: 20px; margin: 36px 0 10px; padding-bottom: 4px; border-bottom: 2px solid var(--accent); break-after: avoid; }
h3 { font-size: 15px; margin: 16px 0 6px; color: var(--muted); text-transform: uppercase; letter-spacing: .04em; break-after: avoid; }
.subtitle { color: var(--muted); margin: 0 0 18px; }
nav { background: var(--band); border: 1px solid var(--rule); padding: 10px 16px; margin: 14px 0 8px; }
nav ol { margin: 4px 0; padding-left: 22px; columns: 2; }
nav a { color: var(--accent); text-decoration: none; }
.summary { display: flex; flex-wrap: wrap; gap: 10px; margin: 12px 0; }
.tile { flex: 1 1 200px; border: 1px solid var(--rule); border-left: 6px solid var(--muted); padding: 8px 12px; }
.tile b { display: block; font-size: 18px; }
.tile.pass { border-left-color: #2e7d32; } .tile.warn { border-left-color: #c77700; } .tile.fail { border-left-color: #c62828; }
table { border-collapse: collapse; width: 100%; margin: 8px 0 12px; font-size: 13px; }
th, td { border-bottom: 1px solid var(--rule); padding: 4px 6px; text-align: left; vertical-align: top; }
th { background: var(--band); font-weight: 600; }
td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr { break-inside: avoid; }
tr.pass td:first-child { border-left: 4px solid #2e7d32; } tr.warn td:first-child { border-left: 4px solid #c77700; }
tr.fail td:first-child { border-left: 4px solid #c62828; }
tr.info td:first-child, tr.advisory td:first-child { border-left: 4px solid #1f5fa8; }
tr.na td:first-child { border-left: 4px solid #9aa3ab; } tr.warn { background: #fff6e5; } tr.fail { background: #fdecea; }
figure { margin: 10px 0 16px; break-inside: avoid; }
figure.wide { grid-column: 1 / -1; }
figure img { display: block; max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { color: var(--muted); font-size: 13px; margin-top: 4px; }
.grid { display: grid; grid-template-columns: repeat(auto-fill, minmax(520px, 1fr)); gap: 4px 16px; }
.accuracy { background: #eef4fb; border-left: 4px solid var(--accent); padding: 6px 12px; margin: 10px 0; font-size: 14px; }
.accuracy ul, .reproduce ul { margin: 4px 0; padding-left: 20px; }
.reproduce code, pre { font: 12.5px/1.4 "DejaVu Sans Mono", "Liberation Mono", monospace; }
.reproduce code { background: var(--band); padding: 1px 4px; word-break: break-all; }
pre { background: var(--band); border: 1px solid var(--rule); padding: 10px; overflow-x: auto; white-space: pre-wrap; }
footer { margin-top: 40px; color: var(--muted); font-size: 12px; border-top: 1px solid var(--rule); padding-top: 8px; }
@page { size: A4; margin: 14mm; }
@media print {
  body { max-width: none; padding: 0; font-size: 11pt; }
  nav { display: none; }
  .grid { grid-template-columns: 1fr 1fr; }
  h2 { break-before: page; }
  section:first-of-type h2 { break-before: auto; }
}
)css";

/// Whether a cell is written as a number ("1.5", "-3e-05", "0.31 %"): the characters of
/// one and a digit (a right-aligned column; the value itself is never needed).
bool readsAsNumber(const std::string& s) {
  bool digit = false;
  for (const char c : s) {
    if (c >= '0' && c <= '9') digit = true;
    else if (std::string_view("+-.eE %").find(c) == std::string_view::npos) return false;
  }
  return digit;
}

std::string list(const std::vector<std::string>& items, bool code) {
  std::string out = "<ul>";
  for (const auto& i : items) out += code ? "<li><code>" + escape(i) + "</code></li>" : "<li>" + escape(i) + "</li>";
  return out + "</ul>";
}

std::string section(const Section& s) {
  std::string out = "<section id=\"" + escape(s.id) + "\">\n<h2>" + escape(s.title) + "</h2>\n" + s.body + "\n";
  if (!s.accuracy.empty()) out += "<div class=\"accuracy\"><h3>How accurate</h3>" + list(s.accuracy, false) + "</div>\n";
  if (!s.commands.empty()) out += "<div class=\"reproduce\"><h3>Reproduce</h3>" + list(s.commands, true) + "</div>\n";
  return out + "</section>\n";
}

}  // namespace

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  return out;
}

std::string base64(std::string_view bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const unsigned v = static_cast<unsigned char>(bytes[i]) << 16 | static_cast<unsigned char>(bytes[i + 1]) << 8 |
                       static_cast<unsigned char>(bytes[i + 2]);
    out += kAlphabet[v >> 18 & 63], out += kAlphabet[v >> 12 & 63], out += kAlphabet[v >> 6 & 63], out += kAlphabet[v & 63];
  }
  if (const std::size_t rest = bytes.size() - i; rest > 0) {
    unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
    if (rest == 2) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    out += kAlphabet[v >> 18 & 63], out += kAlphabet[v >> 12 & 63];
    out += rest == 2 ? kAlphabet[v >> 6 & 63] : '=';
    out += '=';
  }
  return out;
}

std::string pngFigure(std::string_view png, const std::string& alt, const std::string& caption) {
  // A contact sheet (wider than two figures side by side would show it) takes a grid's whole row.
  unsigned width = 0;
  if (png.size() >= 24 && png.substr(12, 4) == "IHDR")
    for (int i = 16; i < 20; ++i) width = width << 8 | static_cast<unsigned char>(png[i]);
  return std::string(width >= 1600 ? "<figure class=\"wide\">" : "<figure>") + "<img alt=\"" + escape(alt) + "\" src=\"data:image/png;base64," + base64(png) + "\"><figcaption>" +
         escape(caption) + "</figcaption></figure>\n";
}

std::string table(const Table& t) {
  std::vector<bool> numeric(t.header.size(), false);
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    bool any = false, all = true;
    for (const auto& r : t.rows)
      if (c < r.size() && !r[c].empty() && r[c] != "-") {
        if (readsAsNumber(r[c])) any = true;
        else all = false;
      }
    numeric[c] = any && all;
  }
  std::string out = "<table>\n<thead><tr>";
  for (const auto& h : t.header) out += "<th>" + escape(h) + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::string cls = r < t.row_classes.size() ? t.row_classes[r] : "";
    out += cls.empty() ? "<tr>" : "<tr class=\"" + escape(cls) + "\">";
    for (std::size_t c = 0; c < t.rows[r].size(); ++c)
      out += (c < numeric.size() && numeric[c] ? "<td class=\"num\">" : "<td>") + escape(t.rows[r][c]) + "</td>";
    out += "</tr>\n";
  }
  return out + "</tbody></table>\n";
}

std::string page(const Page& p) {
  std::string out =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; img-src data:; style-src 'unsafe-inline'\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      escape(p.title) + "</title>\n<style>" + kStyle + "</style>\n</head>\n<body>\n<header>\n<h1>" + escape(p.title) +
      "</h1>\n<p class=\"subtitle\">" + escape(p.subtitle) + "</p>\n</header>\n" + p.summary + "\n<nav><b>Contents</b><ol>";
  for (const auto& s : p.sections) out += "<li><a href=\"#" + escape(s.id) + "\">" + escape(s.title) + "</a></li>";
  out += "</ol></nav>\n<main>\n";
  for (const auto& s : p.sections) out += section(s);
  return out + "</main>\n<footer>" + escape(p.footer) + "</footer>\n</body>\n</html>\n";
}

}  // namespace mmv::html

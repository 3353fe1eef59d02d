#include "sim/core/text.hpp"

#include <algorithm>
#include <charconv>
#include <cctype>

#include <cstdarg>
#include <cstdio>
#include <sstream>

namespace mmv {

std::string strf(const char* format, ...) {
  va_list ap;
  va_start(ap, format);
  char buf[1024];
  std::vsnprintf(buf, sizeof buf, format, ap);
  va_end(ap);
  return buf;
}

namespace {
bool numeric(const std::string& s) {
  return !s.empty() && (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' || s[0] == '+' || s[0] == '.');
}
}  // namespace

std::string Table::text(const std::string& indent) const {
  std::vector<std::size_t> w(header_.size(), 0);
  for (std::size_t c = 0; c < header_.size(); ++c) w[c] = header_[c].size();
  for (const auto& r : rows_)
    for (std::size_t c = 0; c < r.size() && c < w.size(); ++c) w[c] = std::max(w[c], r[c].size());
  std::ostringstream os;
  auto line = [&](const std::vector<std::string>& r, bool head) {
    os << indent;
    for (std::size_t c = 0; c < w.size(); ++c) {
      const std::string cell = c < r.size() ? r[c] : "";
      const std::string pad(w[c] - cell.size(), ' ');
      os << (c ? "  " : "") << ((!head && numeric(cell)) ? pad + cell : cell + (c + 1 < w.size() ? pad : ""));
    }
    os << '\n';
  };
  line(header_, true);
  for (const auto& r : rows_) line(r, false);
  return os.str();
}

std::string Table::markdown() const {
  std::ostringstream os;
  os << '|';
  for (const auto& h : header_) os << ' ' << h << " |";
  os << "\n|";
  for (std::size_t c = 0; c < header_.size(); ++c) os << "---|";
  os << '\n';
  for (const auto& r : rows_) {
    os << '|';
    for (std::size_t c = 0; c < header_.size(); ++c) os << ' ' << (c < r.size() ? r[c] : "") << " |";
    os << '\n';
  }
  return os.str();
}

std::string shortest(double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}
}  // namespace

namespace {
/// The length of the well-formed UTF-8 sequence at s[i] (RFC 3629, table 3-7 of the
/// Unicode standard: no overlong forms such as C0 8E, no surrogates, nothing above
/// U+10FFFF -- what JSON writers accept), or 0 when the bytes there are not one.
std::size_t utf8Length(const std::string& s, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(s[i + k]); };
  const unsigned char c = at(0);
  if (c < 0x80) return 1;
  std::size_t len = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // the allowed range of the second byte
  if (c >= 0xC2 && c <= 0xDF) len = 2;
  else if (c >= 0xE0 && c <= 0xEF) len = 3, lo = c == 0xE0 ? 0xA0 : 0x80, hi = c == 0xED ? 0x9F : 0xBF;
  else if (c >= 0xF0 && c <= 0xF4) len = 4, lo = c == 0xF0 ? 0x90 : 0x80, hi = c == 0xF4 ? 0x8F : 0xBF;
  if (len == 0 || i + len > s.size() || at(1) < lo || at(1) > hi) return 0;
  for (std::size_t k = 2; k < len; ++k)
    if (at(k) < 0x80 || at(k) > 0xBF) return 0;
  return len;
}
}  // namespace

std::string csvColumnName(const std::string& s) {
  std::string out;
  for (unsigned char c : s) {
    if (std::isalnum(c) && c < 128) out += static_cast<char>(std::tolower(c));
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  if (out.empty() || std::isdigit(static_cast<unsigned char>(out.front()))) out = "c" + std::string(out.empty() ? "" : "_") + out;
  return out;
}

std::string unitSlug(const std::string& unit) {
  std::string u;
  for (char c : unit) {
    if (c == '^') continue;  // s^2 -> s2
    u += c;
  }
  return csvColumnName(u);
}

std::string printable(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t len = c < 0x20 || c == 0x7f ? 0 : utf8Length(s, i);
    if (len == 0) {
      out += strf("\\x%02X", c), ++i;
      continue;
    }
    out.append(s, i, len);
    i += len;
  }
  return out;
}

bool isValidUtf8(const std::string& s) {
  for (std::size_t i = 0, len = 0; i < s.size(); i += len)
    if ((len = utf8Length(s, i)) == 0) return false;
  return true;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  for (std::string p; std::getline(ss, p, sep);) out.push_back(p);
  return out;
}

std::string didYouMean(const std::string& name, const std::vector<std::string>& known) {
  std::size_t best_d = 3;  // at most two edits away
  std::vector<const std::string*> best;
  for (const auto& k : known) {
    const std::size_t d = editDistance(name, k);
    if (d >= 3) continue;
    if (d < best_d) best_d = d, best.clear();
    if (d == best_d && best.size() < 4) best.push_back(&k);
  }
  if (best.empty()) return std::string();
  std::string out = " (did you mean ";
  for (std::size_t i = 0; i < best.size(); ++i)
    out += (i == 0 ? "" : i + 1 == best.size() ? " or " : ", ") + ("'" + *best[i] + "'");
  return out + "?)";
}

std::string csvEscape(const std::string& s) {
  std::string out = s;
  for (char& c : out) c = c == ',' ? ';' : c == '"' ? '\'' : c;
  return out;
}

std::string fileNameSafe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

}  // namespace mmv

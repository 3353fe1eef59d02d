#include "sim/core/text.hpp"

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

}  // namespace mmv

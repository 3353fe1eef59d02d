#pragma once
/// A table of strings rendered as aligned text (terminal) or as a Markdown table, so
/// each report is written once for both.

#include <string>
#include <vector>

namespace mmv {

class Table {
 public:
  explicit Table(std::vector<std::string> header) : header_(std::move(header)) {}
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  /// Columns aligned, numbers (cells starting with a digit, sign or dot) to the right.
  std::string text(const std::string& indent = "  ") const;
  std::string markdown() const;
  bool empty() const { return rows_.empty(); }

 private:
  std::vector<std::string> header_;
  std::vector<std::vector<std::string>> rows_;
};

/// The shortest decimal text that reads back as exactly `v` (std::to_chars):
/// 0.0025, not 0.0025000000000000001.
std::string shortest(double v);

/// printf into a std::string.
std::string strf(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace mmv

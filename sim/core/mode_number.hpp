#pragma once
/// A mode as users and reports number it: 1 is the lowest. Where a mode crosses a layer
/// (a command's --mode to a drawing, a study's target modes to the analysis), it is this
/// type and not a plain int, so a 0-based position cannot be passed where a number is
/// meant or the reverse: `index()` is the 0-based position in a list ordered by
/// frequency, and each conversion is spelled out at the one place it happens.

#include <ostream>
#include <vector>

namespace mmv {

class ModeNumber {
 public:
  /// Not yet a mode (number 0): a result field before its solver fills it in.
  constexpr ModeNumber() : number_(0) {}
  constexpr explicit ModeNumber(int number) : number_(number) {}
  /// The mode at 0-based position `index` of a list ordered by frequency.
  static constexpr ModeNumber atIndex(int index) { return ModeNumber(index + 1); }
  constexpr int number() const { return number_; }
  constexpr int index() const { return number_ - 1; }
  friend constexpr bool operator==(ModeNumber a, ModeNumber b) { return a.number_ == b.number_; }
  friend constexpr bool operator!=(ModeNumber a, ModeNumber b) { return a.number_ != b.number_; }
  friend constexpr bool operator<(ModeNumber a, ModeNumber b) { return a.number_ < b.number_; }
  friend std::ostream& operator<<(std::ostream& os, ModeNumber m) { return os << m.number_; }

 private:
  int number_;
};

/// A mode in a JSON record is its number (1: the lowest): nlohmann::json finds this by
/// argument-dependent lookup, so no record can write a 0-based position by mistake.
template <class Json>
void to_json(Json& j, ModeNumber m) {
  j = m.number();
}

/// Mode numbers from plain ones ({1, 2, 3}), where a front end or a test gives them.
inline std::vector<ModeNumber> modeNumbers(const std::vector<int>& numbers) {
  std::vector<ModeNumber> out;
  for (int n : numbers) out.push_back(ModeNumber(n));
  return out;
}

}  // namespace mmv

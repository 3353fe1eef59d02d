#include "sim/io/mat5_writer.hpp"

#include <cstring>
#include <limits>

#include "sim/core/errors.hpp"

namespace mmv {
namespace {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "MAT 5 is written in the machine's byte order, 'IM' (little-endian)");

// Data types and array classes (MAT-File Format, tables 1-1 and 1-3).
constexpr std::uint32_t miINT8 = 1, miINT32 = 5, miUINT32 = 6, miDOUBLE = 9, miMATRIX = 14, miUTF8 = 16, miUTF16 = 17;
constexpr std::uint32_t mxCELL_CLASS = 1, mxCHAR_CLASS = 4, mxDOUBLE_CLASS = 6;

std::uint64_t padded(std::uint64_t n) { return (n + 7) / 8 * 8; }

/// Appends to `storage`; the pieces are (offset, size) in it or an external span,
/// turned into views once storage stops growing.
class Builder {
 public:
  explicit Builder(std::string& storage) : s_(storage) {}

  void u32(std::uint32_t v) { bytes(&v, 4); }
  void bytes(const void* p, std::size_t n) { s_.append(static_cast<const char*>(p), n); }
  void pad() { s_.append(padded(total()) - total(), '\0'); }

  /// A data element of `n` bytes whose data follows (from `data`, or in place for a
  /// large block), padded to 8 bytes.
  void element(std::uint32_t type, const void* data, std::uint64_t n, bool in_place = false) {
    u32(type);
    u32(static_cast<std::uint32_t>(n));
    if (in_place && n > 0) {
      external(data, n);
      s_.append(padded(n) - n, '\0');
    } else {
      bytes(data, n);
      pad();
    }
  }
  /// The array name: the small element format up to 4 bytes (as matio writes it).
  void name(const std::string& name) {
    if (!name.empty() && name.size() <= 4) {
      u32(miINT8 | static_cast<std::uint32_t>(name.size()) << 16);
      char data[4] = {0, 0, 0, 0};
      std::memcpy(data, name.data(), name.size());
      bytes(data, 4);
      return;
    }
    element(miINT8, name.data(), name.size());
  }
  /// Opens a miMATRIX element: flags, dimensions and name; returns where its byte count
  /// goes (endMatrix writes it: everything after that field, to the element's end).
  std::size_t beginMatrix(std::uint32_t cls, std::int32_t rows, std::int32_t cols, const std::string& name) {
    u32(miMATRIX);
    const std::size_t at = s_.size();
    u32(0);
    open_.push_back(total());
    const std::uint32_t flags[2] = {cls, 0};
    element(miUINT32, flags, 8);
    const std::int32_t dims[2] = {rows, cols};
    element(miINT32, dims, 8);
    this->name(name);
    return at;
  }
  void endMatrix(std::size_t at, const std::string& name) {
    const std::uint64_t bytes = total() - open_.back();
    open_.pop_back();
    if (!mat5Fits(bytes))  // a cell of strings past 4 GB (a matrix is refused before it is built)
      throw OutputError(".mat variable " + name + ": " + std::to_string(bytes) + " bytes, more than MAT 5's 4 GB a variable");
    const auto n = static_cast<std::uint32_t>(bytes);
    std::memcpy(&s_[at], &n, 4);
  }
  std::uint64_t total() const { return external_bytes_ + s_.size(); }

  std::vector<std::string_view> pieces() const {
    std::vector<std::string_view> out;
    std::size_t from = 0;
    for (const auto& [at, data, n] : spans_) {
      if (at > from) out.emplace_back(s_.data() + from, at - from);
      out.emplace_back(static_cast<const char*>(data), n);
      from = at;
    }
    if (s_.size() > from) out.emplace_back(s_.data() + from, s_.size() - from);
    return out;
  }

 private:
  struct Span {
    std::size_t at;  ///< where in storage it goes
    const void* data;
    std::size_t n;
  };
  void external(const void* data, std::uint64_t n) {
    spans_.push_back({s_.size(), data, static_cast<std::size_t>(n)});
    external_bytes_ += n;
  }
  std::string& s_;
  std::uint64_t external_bytes_ = 0;
  std::vector<Span> spans_;
  std::vector<std::uint64_t> open_;
};

/// A string as MATLAB char data: UTF-8 bytes when ASCII, else UTF-16 code units (a code
/// point past U+FFFF as a surrogate pair); invalid UTF-8 bytes become U+FFFD.
std::u16string utf16(const std::string& s) {
  std::u16string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    char32_t cp = len == 1 ? c : len == 2 ? c & 0x1f : len == 3 ? c & 0x0f : c & 0x07;
    bool ok = len > 0 && i + static_cast<std::size_t>(len) <= s.size();
    for (int k = 1; ok && k < len; ++k) {
      const auto d = static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]);
      ok = (d >> 6) == 2;
      cp = cp << 6 | (d & 0x3f);
    }
    if (!ok) {
      out.push_back(u'\ufffd');
      ++i;
      continue;
    }
    i += static_cast<std::size_t>(len);
    if (cp >= 0x10000) {
      cp -= 0x10000;
      out.push_back(static_cast<char16_t>(0xd800 + (cp >> 10)));
      out.push_back(static_cast<char16_t>(0xdc00 + (cp & 0x3ff)));
    } else {
      out.push_back(static_cast<char16_t>(cp));
    }
  }
  return out;
}

bool ascii(const std::string& s) {
  for (char c : s)
    if (static_cast<unsigned char>(c) >= 0x80) return false;
  return true;
}

void checkDimension(const std::string& name, long n) {
  if (n > std::numeric_limits<std::int32_t>::max())
    throw OutputError(".mat variable " + name + ": a dimension of " + std::to_string(n) + ", past MAT 5's 2^31 - 1");
}

void writeString(Builder& b, const std::string& s) {
  if (ascii(s)) {
    checkDimension("string", static_cast<long>(s.size()));
    const std::size_t at = b.beginMatrix(mxCHAR_CLASS, 1, static_cast<std::int32_t>(s.size()), "");
    b.element(miUTF8, s.data(), s.size());
    b.endMatrix(at, "string");
    return;
  }
  const std::u16string u = utf16(s);
  checkDimension("string", static_cast<long>(u.size()));
  const std::size_t at = b.beginMatrix(mxCHAR_CLASS, 1, static_cast<std::int32_t>(u.size()), "");
  b.element(miUTF16, u.data(), 2 * u.size());
  b.endMatrix(at, "string");
}

}  // namespace

bool mat5Fits(std::uint64_t bytes) { return bytes <= kMat5MaxElementBytes; }

std::vector<std::string_view> mat5Pieces(const MatContents& c, std::string& storage) {
  storage.clear();
  // Checked first: nothing is built (or written) for a file that cannot hold them all.
  for (const auto& [name, m] : c.matrices) {
    checkDimension(name, static_cast<long>(m.rows()));
    checkDimension(name, static_cast<long>(m.cols()));
    const std::uint64_t data = 8 * static_cast<std::uint64_t>(m.size());
    if (!mat5Fits(data + 64 + padded(name.size())))
      throw OutputError(".mat variable " + name + ": " + std::to_string(m.rows()) + " x " + std::to_string(m.cols()) +
                        " doubles, more than MAT 5's 4 GB a variable (write fewer states)");
  }
  // The header: 116 bytes of text, 8 of subsystem offset (none), version 0x0100, 'IM'.
  std::string text = "MATLAB 5.0 MAT-file, Platform: GLNXA64, Created by: mmvlab";
  text.resize(116, ' ');
  storage = text + std::string(8, ' ');
  const std::uint16_t version = 0x0100;
  storage.append(reinterpret_cast<const char*>(&version), 2);
  storage += "IM";
  Builder b(storage);
  for (const auto& [name, m] : c.matrices) {
    const std::size_t at = b.beginMatrix(mxDOUBLE_CLASS, static_cast<std::int32_t>(m.rows()), static_cast<std::int32_t>(m.cols()), name);
    b.element(miDOUBLE, m.data(), 8 * static_cast<std::uint64_t>(m.size()), true);
    b.endMatrix(at, name);
  }
  for (const auto& [name, items] : c.strings) {
    checkDimension(name, static_cast<long>(items.size()));
    const std::size_t at = b.beginMatrix(mxCELL_CLASS, static_cast<std::int32_t>(items.size()), 1, name);
    for (const std::string& s : items) writeString(b, s);
    b.endMatrix(at, name);
  }
  return b.pieces();
}

}  // namespace mmv

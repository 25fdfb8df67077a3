#pragma once
// Line and column of a byte in a text, as the JSON parser's own messages count them (both from 1,
// the column in bytes), so that every refusal of the case file's text points at one place alike.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>

namespace silodem {

struct TextPosition {
  std::size_t line = 1, column = 1;

  /// Moves past `n` bytes of text (chunk by chunk: a file need not be held to be counted).
  void advance(const char* text, std::size_t n) {
    const char* end = text + n;
    for (const char* nl; (nl = static_cast<const char*>(std::memchr(text, '\n', std::size_t(end - text))));) {
      ++line;
      column = 1;
      text = nl + 1;
    }
    column += std::size_t(end - text);
  }
  std::string describe() const { return "line " + std::to_string(line) + ", column " + std::to_string(column); }
};

/// The position of byte `offset` of `text`.
inline TextPosition position_in(const std::string& text, std::size_t offset) {
  TextPosition p;
  p.advance(text.data(), std::min(offset, text.size()));
  return p;
}

}  // namespace silodem

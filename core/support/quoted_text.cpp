#include "core/support/quoted_text.h"

namespace gps {

namespace {

// The length of the well-formed UTF-8 sequence at the start of `text`, or 0 where its first byte
// does not begin one (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
size_t utf8_length(std::string_view text) {
  const auto byte = [&](size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  const auto continuation = [&](size_t i, unsigned lo = 0x80, unsigned hi = 0xBF) {
    return byte(i) >= lo && byte(i) <= hi;
  };
  const unsigned c = byte(0);
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return continuation(1) ? 2 : 0;
  if (c == 0xE0) return continuation(1, 0xA0) && continuation(2) ? 3 : 0;
  if (c == 0xED) return continuation(1, 0x80, 0x9F) && continuation(2) ? 3 : 0;
  if (c >= 0xE1 && c <= 0xEF) return continuation(1) && continuation(2) ? 3 : 0;
  if (c == 0xF0) return continuation(1, 0x90) && continuation(2) && continuation(3) ? 4 : 0;
  if (c >= 0xF1 && c <= 0xF3) return continuation(1) && continuation(2) && continuation(3) ? 4 : 0;
  if (c == 0xF4) return continuation(1, 0x80, 0x8F) && continuation(2) && continuation(3) ? 4 : 0;
  return 0;
}

void append_hex(std::string& out, unsigned char c) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  out += "\\x";
  out += kDigits[c >> 4];
  out += kDigits[c & 15];
}

// Appends at most `max_characters` characters of `text` escaped; returns whether any were left out.
bool append_escaped(std::string& out, std::string_view text, size_t max_characters) {
  size_t characters = 0;
  for (size_t i = 0; i < text.size(); ++characters) {
    if (characters == max_characters) return true;
    const unsigned char c = static_cast<unsigned char>(text[i]);
    size_t n = utf8_length(text.substr(i));
    const bool c1_control = n == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    if (n == 0 || c1_control || c < 0x20 || c == 0x7F) {
      for (size_t k = 0; k < (c1_control ? 2u : 1u); ++k) append_hex(out, static_cast<unsigned char>(text[i + k]));
      i += c1_control ? 2 : 1;
      continue;
    }
    out.append(text.substr(i, n));
    i += n;
  }
  return false;
}

}  // namespace

std::string escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  append_escaped(out, text, text.size());
  return out;
}

std::string quoted_token(std::string_view token) {
  std::string out = "'";
  if (append_escaped(out, token, kMaxQuotedCharacters)) out += "…";
  out += "'";
  return out;
}

}  // namespace gps

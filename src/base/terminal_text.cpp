#include "base/terminal_text.h"

#include <cstdio>

namespace tcsb {
namespace {

/// Length of the valid UTF-8 sequence starting at text[i], or 0 when the byte there does not start one.
std::size_t utf8_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  if (lead >= 0xC2 && lead <= 0xDF)
    length = 2;
  else if (lead >= 0xE0 && lead <= 0xEF)
    length = 3;
  else if (lead >= 0xF0 && lead <= 0xF4)
    length = 4;
  if (length == 0 || i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  // Overlong three- and four-byte forms, surrogates and code points above U+10FFFF are not UTF-8 either.
  if (lead == 0xE0 && byte(i + 1) < 0xA0) return 0;
  if (lead == 0xED && byte(i + 1) > 0x9F) return 0;
  if (lead == 0xF0 && byte(i + 1) < 0x90) return 0;
  if (lead == 0xF4 && byte(i + 1) > 0x8F) return 0;
  return length;
}

std::string escaped(const char* pattern, unsigned value) {
  char buf[8];
  std::snprintf(buf, sizeof buf, pattern, value);
  return buf;
}

/// The text printed for the character at text[i] (escaped or as is) and how many input bytes it covers.
std::string_view next_unit(std::string_view text, std::size_t i, std::string& scratch, std::size_t& consumed) {
  const unsigned char c = static_cast<unsigned char>(text[i]);
  consumed = 1;
  if (c < 0x20 || c == 0x7F) return scratch = escaped("\\x%02x", c);
  if (c < 0x80) return text.substr(i, 1);
  const std::size_t length = utf8_length(text, i);
  if (length == 0) return scratch = escaped("\\x%02x", c);
  consumed = length;
  const unsigned char second = static_cast<unsigned char>(text[i + 1]);
  if (c == 0xC2 && second <= 0x9F) return scratch = escaped("\\u%04x", second);  // U+0080..U+009F
  return text.substr(i, length);
}

}  // namespace

std::string terminal_safe(std::string_view text, std::size_t max_bytes) {
  std::string out, scratch;
  std::size_t i = 0;
  while (i < text.size()) {
    std::size_t consumed = 0;
    const std::string_view unit = next_unit(text, i, scratch, consumed);
    if (out.size() + unit.size() > max_bytes) break;
    out += unit;
    i += consumed;
  }
  if (i < text.size()) out += "… (" + std::to_string(text.size() - i) + " more bytes)";
  return out;
}

}  // namespace tcsb

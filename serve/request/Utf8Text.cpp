#include "serve/request/Utf8Text.h"

#include <algorithm>

namespace figment::serve {

namespace {

// The length of the well-formed UTF-8 sequence starting at `at`, or 0 where none starts
// there (the Unicode Standard's table 3-7 of well-formed byte sequences).
size_t sequenceAt(std::string_view text, size_t at) {
  const auto byte = [&](size_t i) { return i < text.size() ? static_cast<unsigned char>(text[i]) : 0u; };
  const unsigned lead = byte(at);
  const auto tail = [&](size_t i, unsigned low = 0x80, unsigned high = 0xbf) {
    return byte(at + i) >= low && byte(at + i) <= high;
  };
  if (lead < 0x80) return 1;
  if (lead >= 0xc2 && lead <= 0xdf) return tail(1) ? 2 : 0;
  if (lead == 0xe0) return tail(1, 0xa0) && tail(2) ? 3 : 0;        // no overlong forms
  if (lead == 0xed) return tail(1, 0x80, 0x9f) && tail(2) ? 3 : 0;  // no surrogates
  if (lead >= 0xe1 && lead <= 0xef) return tail(1) && tail(2) ? 3 : 0;
  if (lead == 0xf0) return tail(1, 0x90) && tail(2) && tail(3) ? 4 : 0;        // no overlong forms
  if (lead == 0xf4) return tail(1, 0x80, 0x8f) && tail(2) && tail(3) ? 4 : 0;  // nothing past U+10FFFF
  if (lead >= 0xf1 && lead <= 0xf3) return tail(1) && tail(2) && tail(3) ? 4 : 0;
  return 0;
}

}  // namespace

bool Utf8Text::valid(std::string_view text) {
  for (size_t at = 0; at < text.size();) {
    const size_t length = sequenceAt(text, at);
    if (length == 0) return false;
    at += length;
  }
  return true;
}

std::string Utf8Text::percentEncoded(std::string_view text) {
  static const char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte > 0x20 && byte < 0x7f && byte != '%') {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 0xf];
    }
  }
  return out;
}

std::string Utf8Text::shown(std::string_view text, size_t most) {
  if (!valid(text)) {
    const std::string encoded = percentEncoded(text);
    size_t end = std::min(most, encoded.size());
    // A cut inside a %XX leaves it out whole ('%' itself is always encoded: each one starts a %XX).
    if (end < encoded.size() && end >= 1 && encoded[end - 1] == '%')
      end -= 1;
    else if (end < encoded.size() && end >= 2 && encoded[end - 2] == '%')
      end -= 2;
    return encoded.substr(0, end);
  }
  size_t end = 0;
  while (end < text.size()) {
    const size_t length = sequenceAt(text, end);
    if (end + length > most) break;
    end += length;
  }
  return std::string(text.substr(0, end));
}

}  // namespace figment::serve

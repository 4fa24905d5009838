#pragma once
// Text a client sent, as the service's JSON answers may show it. A URL's query and path are
// percent-decoded into bytes, and those bytes need not be UTF-8 (`stature=%ff`); JSON is
// UTF-8 text, and nlohmann::json refuses to write anything else (it throws). So what an
// answer echoes of a request goes through shown(): UTF-8 as it is, anything else
// percent-encoded again, and either cut to a bound on a whole character.

#include <cstddef>
#include <string>
#include <string_view>

namespace figment::serve {

class Utf8Text {
 public:
  // Whether `text` is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates,
  // nothing past U+10FFFF); what nlohmann::json writes without throwing.
  static bool valid(std::string_view text);
  // `text` percent-encoded: every byte outside printable ASCII, and '%', as %XX.
  static std::string percentEncoded(std::string_view text);
  // `text` for an answer: valid UTF-8 as it is, else percent-encoded; at most `most` bytes,
  // cut before a character (or a %XX) that would pass the bound.
  static std::string shown(std::string_view text, size_t most);
};

}  // namespace figment::serve

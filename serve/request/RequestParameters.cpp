#include "serve/request/RequestParameters.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "serve/request/Utf8Text.h"

namespace figment::serve {

std::string utf8Prefix(const std::string& text, size_t bytes) {
  if (text.size() <= bytes) return text;
  size_t end = bytes;
  while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0) == 0x80) --end;  // text[end] continues a character
  return text.substr(0, end);
}

ParameterError RequestParameters::refusal(const std::string& parameter, const std::string& value,
                                          const std::string& error, const std::string& accepted) {
  return {error, parameter, Utf8Text::shown(value, 64), accepted};
}

std::optional<ParameterError> RequestParameters::textError(const std::string& name, const std::string& value) {
  const std::string accepted = "UTF-8 text (its bytes percent-encoded in the URL)";
  if (!Utf8Text::valid(name))
    return refusal(Utf8Text::shown(name, 64), value, "a parameter name that is not UTF-8", accepted);
  if (!Utf8Text::valid(value)) return refusal(name, value, "not UTF-8", accepted);
  return std::nullopt;
}

bool RequestParameters::number(const std::string& text, double& value) {
  if (text.empty() || text.size() > 32) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::fixed);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

QueryParameters RequestParameters::split(const std::string& text) {
  QueryParameters parameters;
  size_t start = 0;
  while (start < text.size()) {
    const size_t amp = std::min(text.find('&', start), text.size());
    const std::string pair = text.substr(start, amp - start);
    const size_t eq = pair.find('=');
    parameters.emplace_back(pair.substr(0, eq), eq == std::string::npos ? "" : pair.substr(eq + 1));
    start = amp + 1;
  }
  return parameters;
}

}  // namespace figment::serve

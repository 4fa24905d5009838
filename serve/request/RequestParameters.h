#pragma once
// What both of the service's requests (RenderRequest, FitRequest) are made of: decoded
// name=value pairs, the refusal of one, the limits on them, and the canonical text they are
// written back as. Neither request includes the other: they share this.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace figment::serve {

// A request's decoded query parameters, in the order given.
using QueryParameters = std::vector<std::pair<std::string, std::string>>;

// What is wrong with a request, as the 400 answer's JSON says it.
struct ParameterError {
  std::string error;      // one line
  std::string parameter;  // the parameter's name ("" for the request as a whole)
  std::string value;      // what was given (cut to 64 bytes)
  std::string accepted;   // what is accepted
};

// Limits on what one request may ask (docs/service.md).
struct RequestLimits {
  static constexpr int kMinSide = 64, kMaxSide = 1600;  // pixels
  static constexpr int kMaxPixels = 1600 * 1200;
  static constexpr int kMaxGarments = 3;
  static constexpr int kMaxParameters = 16;
  static constexpr size_t kMaxValueLength = 200;  // bytes
};

// At most `bytes` bytes of `text`, cut before a UTF-8 character that would not fit whole:
// what a refusal quotes of a value stays the UTF-8 it was (the answer is JSON).
std::string utf8Prefix(const std::string& text, size_t bytes);

class RequestParameters {
 public:
  // The refusal of `value` given for `parameter`: the value shown as text, cut to 64 bytes
  // (serve/request/Utf8Text.h).
  static ParameterError refusal(const std::string& parameter, const std::string& value, const std::string& error,
                                const std::string& accepted);
  // The refusal of a parameter whose name or value is not UTF-8 (a query is percent-decoded
  // into bytes, any bytes): the answer is JSON, UTF-8 text, so it names the parameter and
  // shows the value percent-encoded; nullopt when both are text. Both requests' parsers ask
  // it first.
  static std::optional<ParameterError> textError(const std::string& name, const std::string& value);
  // A plain decimal number, nothing before or after it; no inf or nan.
  static bool number(const std::string& text, double& value);
  // Splits canonical text ("a=1&b=2", as the requests' canonical() write it: nothing to
  // decode) into its pairs (the worker's side of the pipe).
  static QueryParameters split(const std::string& text);
};

}  // namespace figment::serve

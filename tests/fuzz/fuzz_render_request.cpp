// libFuzzer target: figment-serve's request parser (serve/request/RenderRequest.cpp) on any query
// string, split as the server splits one (name=value pairs at '&'). A request it accepts
// must read back from its canonical text to the same text (the ETag and the worker rely
// on that); a refusal must name what it refused within the bounds the 400 answer has.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "serve/request/RenderRequest.h"

namespace {

figment::serve::QueryParameters split(const std::string& query) {
  figment::serve::QueryParameters parameters;
  size_t start = 0;
  while (start <= query.size()) {
    size_t amp = query.find('&', start);
    if (amp == std::string::npos) amp = query.size();
    const std::string pair = query.substr(start, amp - start);
    const size_t eq = pair.find('=');
    if (!pair.empty()) parameters.emplace_back(pair.substr(0, eq), eq == std::string::npos ? "" : pair.substr(eq + 1));
    start = amp + 1;
  }
  return parameters;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using figment::serve::ParameterError;
  using figment::serve::RenderRequest;
  const auto parsed = RenderRequest::parse(split(std::string(reinterpret_cast<const char*>(data), size)));
  if (const auto* error = std::get_if<ParameterError>(&parsed)) {
    if (error->error.empty() || error->accepted.empty() || error->value.size() > 64) std::abort();
    return 0;
  }
  const std::string canonical = std::get<RenderRequest>(parsed).canonical();
  const auto again = RenderRequest::parseCanonical(canonical);
  if (!std::holds_alternative<RenderRequest>(again) || std::get<RenderRequest>(again).canonical() != canonical)
    std::abort();
  return 0;
}

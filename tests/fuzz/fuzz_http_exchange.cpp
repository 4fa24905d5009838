// libFuzzer target: figment-serve's whole HTTP exchange, in process. An input is the bytes a
// client sends on one connection (request lines, header fields, bodies; several requests one
// after another); HttpService::exchange answers them through cpp-httplib's own request
// reader and the service's routes, refusals and error handlers, as on a socket, and gives
// back each answer's bytes. The service has no workers (ServeOptions::workers 0): a render
// or fit it judges valid is refused at the pool with 503, so no drape runs. Each answer must
//  - be well formed (tests/support/HttpAnswer.h): a status line, header names that are
//    tokens, values without control bytes, one Content-Length the body keeps to;
//  - be no 5xx but the pool's 503 with Retry-After: anything else is the server's to judge;
//  - say Allow with a 405;
//  - be JSON when it refuses;
//  - carry JSON that parses (nlohmann refuses text that is not UTF-8) as an object, with an
//    "error" in a refusal, and hold U+FFFD only where the request held it: the service's
//    JSON writer replaces bytes that are not UTF-8, so an echo of raw bytes shows as U+FFFD.
// The body of an answer to a Range request (cpp-httplib's doing: part of the answer) or a
// compressed one (Accept-Encoding) is not JSON text: its form is checked, not its JSON.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "serve/http/HttpService.h"
#include "tests/support/HttpAnswer.h"

namespace {

using figment::test::HttpAnswer;

figment::serve::HttpService& service() {
  static figment::serve::HttpService* const instance = [] {
    figment::serve::ServeOptions options;
    options.workers = 0;                                  // nothing renders: a valid render or fit is 503 at the pool
    options.renderRate = 0;                               // no rate limit, so valid requests reach the pool
    options.scenesFolder = FIGMENT_SOURCE_DIR "/scenes";  // its size chart: /api/fit judges requests
    return new figment::serve::HttpService(options, "");
  }();
  return *instance;
}

[[noreturn]] void fail(const std::string& what, std::string_view answer) {
  std::fprintf(stderr, "fuzz_http_exchange: %s\n--- answer:\n%.*s\n", what.c_str(),
               static_cast<int>(std::min<size_t>(answer.size(), 2000)), answer.data());
  std::abort();
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Whether the input holds U+FFFD's bytes, as sent or once its %XX and %uXXXX escapes are
// decoded (cpp-httplib decodes both).
bool holdsReplacement(std::string_view input) {
  constexpr std::string_view kReplacement = "\xEF\xBF\xBD";
  if (input.find(kReplacement) != std::string_view::npos) return true;
  std::string decoded;
  for (size_t i = 0; i < input.size(); ++i) {
    if (input[i] == '%' && i + 5 < input.size() && (input[i + 1] == 'u' || input[i + 1] == 'U')) {
      int code = 0;
      bool hex = true;
      for (size_t k = 2; k < 6; ++k)
        hex = hex && hexValue(input[i + k]) >= 0, code = code * 16 + hexValue(input[i + k]);
      if (hex && code == 0xFFFD) return true;
    }
    if (input[i] == '%' && i + 2 < input.size() && hexValue(input[i + 1]) >= 0 && hexValue(input[i + 2]) >= 0) {
      decoded += static_cast<char>(hexValue(input[i + 1]) * 16 + hexValue(input[i + 2]));
      i += 2;
    } else {
      decoded += input[i];
    }
  }
  return decoded.find(kReplacement) != std::string::npos;
}

void checkJson(const HttpAnswer& answer, bool inputHoldsReplacement, std::string_view bytes) {
  if (answer.body.empty()) return;  // a HEAD's answer
  const nlohmann::json body = nlohmann::json::parse(answer.body, nullptr, false);
  if (!body.is_object()) fail("a JSON body that is not a JSON object (or not UTF-8)", bytes);
  if (answer.status >= 400 && !(body.contains("error") && body["error"].is_string()))
    fail("a refusal without an error", bytes);
  if (!inputHoldsReplacement && answer.body.find("\xEF\xBF\xBD") != std::string::npos)
    fail("U+FFFD in the answer, none in the request: bytes that were not UTF-8 echoed", bytes);
}

void checkAnswer(std::string_view bytes, bool inputHoldsReplacement) {
  HttpAnswer answer;
  if (const std::string error = figment::test::readAnswer(bytes, answer); !error.empty()) fail(error, bytes);
  if (answer.status >= 500 && !(answer.status == 503 && !answer.header("Retry-After").empty()))
    fail("a 5xx that is not the pool's 503", bytes);
  if (answer.status == 405 && answer.header("Allow").empty()) fail("a 405 without Allow", bytes);
  const bool partial = answer.count("Content-Range") > 0 || answer.status == 416 ||
                       answer.header("Content-Type").rfind("multipart/byteranges", 0) == 0;
  const bool encoded = answer.count("Content-Encoding") > 0;
  if (partial || encoded) return;
  if (answer.status >= 400 && !answer.body.empty() && answer.header("Content-Type") != "application/json")
    fail("a refusal that is not JSON", bytes);
  if (answer.header("Content-Type") == "application/json") checkJson(answer, inputHoldsReplacement, bytes);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const bool inputHoldsReplacement = holdsReplacement(input);
  for (const std::string& answer : service().exchange(input)) checkAnswer(answer, inputHoldsReplacement);
  return 0;
}

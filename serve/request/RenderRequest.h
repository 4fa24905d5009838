#pragma once
// GET /api/render's parameters, checked and made canonical. A request is parameters
// only: names from the catalogue, numbers and hex colours; nothing in it names a file or
// holds scene text. Two requests that draw the same picture have the same canonical()
// text, so its digest names the image (the ETag) and identical requests in flight drape
// once.

#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "serve/request/Catalogue.h"
#include "sim/garment/SizeChart.h"

namespace figment::serve {

// One garment of the outfit, innermost first.
struct OutfitItem {
  std::string style;   // a Catalogue style
  std::string size;    // a Catalogue size
  std::string colour;  // rrggbb, lower case
};

// What is wrong with a request, as the 400 answer's JSON says it.
struct ParameterError {
  std::string error;      // one line
  std::string parameter;  // the parameter's name ("" for the request as a whole)
  std::string value;      // what was given (cut to 64 bytes)
  std::string accepted;   // what is accepted
};

// At most `bytes` bytes of `text`, cut before a UTF-8 character that would not fit whole:
// what a refusal quotes of a value stays the UTF-8 it was (the answer is JSON).
std::string utf8Prefix(const std::string& text, size_t bytes);

// Limits on what one request may ask (docs/service.md).
struct RequestLimits {
  static constexpr int kMinSide = 64, kMaxSide = 1600;  // pixels
  static constexpr int kMaxPixels = 1600 * 1200;
  static constexpr int kMaxGarments = 3;
  static constexpr int kMaxParameters = 16;
  static constexpr size_t kMaxValueLength = 200;  // bytes
};

class RenderRequest {
 public:
  using Parameters = std::vector<std::pair<std::string, std::string>>;

  // The request from decoded query parameters; absent ones take the defaults (the default
  // body, in the dress, studio light, from the front, 800x600). With `sex` the body is
  // MakeHuman's made to the measurements and the outfit's sizes are `chart`'s (graded
  // garments of sim/garment/GarmentStyle.h's styles); without a chart `sex` is refused.
  static std::variant<RenderRequest, ParameterError> parse(const Parameters& parameters,
                                                           const SizeChart* chart = nullptr);

  // Every parameter the request takes (serve/http/openapi.json lists these; test_serve checks it).
  static std::vector<std::string> parameterNames();

  // name=value&... in a fixed order, numbers rounded to what changes the picture (mm,
  // tenths of a degree): parse(canonical()) gives the same request.
  std::string canonical() const;
  // The part that shapes the drape (body, pose, garment styles and sizes): requests that
  // differ only in colours, light, view or size share one drape.
  std::string drapeKey() const;
  // The part that shapes the scene (all but view and size).
  std::string sceneKey() const;
  // Splits canonical text ("a=1&b=2", as canonical() writes it: nothing to decode) into its
  // pairs; the fit request's parser shares it.
  static Parameters splitCanonical(const std::string& text, size_t start = 0);
  // Parses canonical text back (the worker's side of the pipe).
  static std::variant<RenderRequest, ParameterError> parseCanonical(const std::string& text,
                                                                    const SizeChart* chart = nullptr);
  // The refusal of a parameter whose name or value is not UTF-8 (a query is percent-decoded
  // into bytes, any bytes): the answer is JSON, UTF-8 text, so it names the parameter and
  // shows the value percent-encoded (serve/request/Utf8Text.h); nullopt when both are text. Both
  // parsers (this and FitRequest) ask it first.
  static std::optional<ParameterError> textError(const std::string& name, const std::string& value);

  // The picture's anti-aliasing (session/SceneRenderer.h's k x k samples a pixel):
  // figment-view's 3, fewer where the drawn image would pass four times the largest
  // picture's pixels (1600 x 1200 takes 2), so a worker's off-screen buffers stay within
  // about 8 Mpixels. Of the size alone: the canonical text still names the picture.
  int supersample() const;

  // "&sex=..." when the body is measured, else "": a Mannequin's texts are as they were.
  std::string sexText() const { return sex.empty() ? "" : "&sex=" + sex; }

  BodyMeasures body;  // m
  std::string sex;    // "" for the scaled Mannequin; female or male for a measured HumanBody
  std::string skin;   // rrggbb
  std::string pose;   // a Catalogue pose
  std::vector<OutfitItem> outfit;
  std::string light;                  // a Catalogue light
  double azimuth = 0, elevation = 0;  // degrees
  int width = 800, height = 600;      // pixels
  std::string format = "png";         // png, or glb: the dressed body as glTF binary
  // "" (the garments in their colours), "stretch", or with a sex also "ease", "pressure":
  // each garment coloured by that fit map's bands (sim/fit/FitMap.h), blue at rest (far
  // from the skin) to red at the fabric's limit (on the skin). Same drape.
  std::string fitMap;
};

}  // namespace figment::serve

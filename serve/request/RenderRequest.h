#pragma once
// GET /api/render's parameters, checked and made canonical. A request is parameters
// only: names from ShopperChoices, numbers and hex colours; nothing in it names a file or
// holds scene text. Two requests that draw the same picture have the same canonical()
// text, so its digest names the image (the ETag) and identical requests in flight drape
// once.

#include <string>
#include <variant>
#include <vector>

#include "serve/request/RequestParameters.h"
#include "serve/request/ShopperChoices.h"
#include "sim/garment/SizeChart.h"

namespace figment::serve {

// One garment of the outfit, innermost first.
struct OutfitItem {
  std::string style;   // a ShopperChoices style
  std::string size;    // a ShopperChoices size
  std::string colour;  // rrggbb, lower case
};

class RenderRequest {
 public:
  // The request from decoded query parameters; absent ones take the defaults (the default
  // body, in the dress, studio light, from the front, 800x600). With `sex` the body is
  // MakeHuman's made to the measurements and the outfit's sizes are `chart`'s (graded
  // garments of sim/garment/GarmentStyle.h's styles); without a chart `sex` is refused.
  static std::variant<RenderRequest, ParameterError> parse(const QueryParameters& parameters,
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
  // Parses canonical text back (the worker's side of the pipe).
  static std::variant<RenderRequest, ParameterError> parseCanonical(const std::string& text,
                                                                    const SizeChart* chart = nullptr);
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
  std::string pose;   // a ShopperChoices pose
  std::vector<OutfitItem> outfit;
  std::string light;                  // a ShopperChoices light
  double azimuth = 0, elevation = 0;  // degrees
  int width = 800, height = 600;      // pixels
  std::string format = "png";         // png, or glb: the dressed body as glTF binary
  // "" (the garments in their colours), "stretch", or with a sex also "ease", "pressure":
  // each garment coloured by that fit map's bands (sim/fit/FitMap.h), blue at rest (far
  // from the skin) to red at the fabric's limit (on the skin). Same drape.
  std::string fitMap;
};

}  // namespace figment::serve

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

namespace figment {
class GarmentCatalogue;
}

namespace figment::serve {

// One garment of the outfit, innermost first.
struct OutfitItem {
  std::string style;   // a catalogue style (MadeBodyChoices), or on the Mannequin a ShopperChoices one
  std::string size;    // the chart's letter code; "" on the Mannequin (the paper's pattern as cut)
  std::string colour;  // rrggbb, lower case
};

class RenderRequest {
 public:
  // The request from decoded query parameters; absent ones take the defaults: the made
  // body (MakeHuman's, made to the measurements: women's unless `sex` says, the chart's M
  // without measurements) in the first style the catalogue sells to it, in its size, studio
  // light, from the front, 800x600. body=mannequin is the paper's scaled Mannequin in its
  // patterns as cut. Without a catalogue only the Mannequin is drawn.
  static std::variant<RenderRequest, ParameterError> parse(const QueryParameters& parameters,
                                                           const GarmentCatalogue* catalogue = nullptr);

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
                                                                    const GarmentCatalogue* catalogue = nullptr);
  // The picture's anti-aliasing (session/SceneRenderer.h's k x k samples a pixel):
  // figment-view's 3, fewer where the drawn image would pass four times the largest
  // picture's pixels (1600 x 1200 takes 2), so a worker's off-screen buffers stay within
  // about 8 Mpixels. Of the size alone: the canonical text still names the picture.
  int supersample() const;

  // "&sex=..." for a made body, "&body=mannequin" for the Mannequin.
  std::string bodyText() const { return sex.empty() ? "&body=mannequin" : "&sex=" + sex; }
  bool mannequin() const { return sex.empty(); }

  BodyMeasures body;  // m
  std::string sex;    // female or male: a made HumanBody; "" for the scaled Mannequin
  std::string skin;   // rrggbb
  // A made body's plain underwear (nodes/body/HumanBody.h's base layer): on by default,
  // `underwear=off` draws the body bare. Not drawn on the Mannequin. Shapes the scene, not
  // the drape (the layer lies inside the cloth's clearance).
  bool underwear = true;
  std::string pose;  // a ShopperChoices pose
  std::vector<OutfitItem> outfit;
  std::string light;                  // a ShopperChoices light
  double azimuth = 0, elevation = 0;  // degrees
  int width = 800, height = 600;      // pixels
  std::string format = "png";         // png, or glb: the dressed body as glTF binary
  // "" (the garments in their colours), "stretch", or on a made body also "ease", "pressure":
  // each garment coloured by that fit map's bands (sim/fit/FitMap.h), blue at rest (far
  // from the skin) to red at the fabric's limit (on the skin). Same drape.
  std::string fitMap;
};

}  // namespace figment::serve

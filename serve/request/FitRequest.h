#pragma once
// GET /api/fit's parameters, checked and made canonical: a sex, a style the catalogue sells
// to it (MadeBodyChoices.h: the styles a render dresses a made body in) and the shopper's
// four measurements, each within
// the range the chart's bodies span for that sex widened by two sizes
// (serve/request/BodyMeasuresText.h). Like a render request it is parameters only; a worker
// is told it is a fit by its job's kind (serve/workers/JobKind.h), not by its text.

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

class FitRequest {
 public:
  // Every parameter the request takes (serve/http/openapi.json lists these; test_serve checks it).
  static std::vector<std::string> parameterNames();

  // Every parameter is required: sex, style, stature, bust, waist, hips.
  static std::variant<FitRequest, ParameterError> parse(const QueryParameters& parameters,
                                                        const GarmentCatalogue& catalogue);
  // name=value&... in a fixed order, metres to the mm: parseCanonical gives it back.
  std::string canonical() const;
  static std::variant<FitRequest, ParameterError> parseCanonical(const std::string& text,
                                                                 const GarmentCatalogue& catalogue);

  Sex sex = Sex::Female;
  std::string style;  // a catalogue style the service dresses
  BodyMeasures body;  // m
};

}  // namespace figment::serve

#pragma once
// GET /api/fit's parameters, checked and made canonical: a sex, a style of the size chart's
// garments (sim/garment/GarmentStyle.h) and the shopper's four measurements, each within
// the range the chart's bodies span for that sex widened by two sizes
// (serve/request/BodyMeasuresText.h). Like a render request it is parameters only; a worker
// is told it is a fit by its job's kind (serve/workers/JobKind.h), not by its text.

#include <nlohmann/json_fwd.hpp>
#include <string>
#include <variant>
#include <vector>

#include "serve/request/RequestParameters.h"
#include "serve/request/ShopperChoices.h"
#include "sim/garment/SizeChart.h"

namespace figment::serve {

class FitRequest {
 public:
  // The size chart of a scenes folder (scenes/sizes/chart.txt): the server's and its workers'.
  static std::string chartPath(const std::string& scenesFolder) { return scenesFolder + "/sizes/chart.txt"; }

  // Every parameter the request takes (serve/http/openapi.json lists these; test_serve checks it).
  static std::vector<std::string> parameterNames();

  // Every parameter is required: sex, style, stature, bust, waist, hips.
  static std::variant<FitRequest, ParameterError> parse(const QueryParameters& parameters, const SizeChart& chart);
  // name=value&... in a fixed order, metres to the mm: parseCanonical gives it back.
  std::string canonical() const;
  static std::variant<FitRequest, ParameterError> parseCanonical(const std::string& text, const SizeChart& chart);

  // /api/catalogue's "fit": each style with the chart's sizes per sex, and the ranges.
  static nlohmann::json choicesJson(const SizeChart& chart);

  Sex sex = Sex::Female;
  std::string style;  // a sim/garment style name
  BodyMeasures body;  // m
};

}  // namespace figment::serve

#pragma once
// What a shopper's own body may be and wear: the body MakeHuman makes to the shopper's
// measurements (the service's default body), dressed from the shop's garment catalogue
// (io/GarmentCatalogue.h) in the size chart's sizes. One size vocabulary everywhere: a
// style's sizes are those the catalogue sells it in for the body's sex, named as the chart
// names them, in a render, a fit, the precompute grid and GET /api/catalogue alike.
//
// A style is a generator's garment graded to a size (sim/garment/GarmentStyle.h) or a
// shop's own, sewn from its size's sewing pattern (a pattern style: scenes/patterns/); the
// service dresses both, a sewn one standing (RenderRequest: it is sewn on the body at rest).

#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "serve/request/RequestParameters.h"
#include "serve/request/ShopperChoices.h"
#include "sim/garment/SizeChart.h"

namespace figment {
class GarmentCatalogue;
struct CatalogueStyle;
}  // namespace figment

namespace figment::serve {

class MadeBodyChoices {
 public:
  // The catalogue's path in a scenes folder (scenes/catalogue/index.txt).
  static std::string cataloguePath(const std::string& scenesFolder) { return scenesFolder + "/catalogue/index.txt"; }
  // The scenes folder's catalogue, read; throws as GarmentCatalogue's constructor. Shared:
  // its holder need not see the type (the HTTP side keeps Eigen's headers out of its own).
  static std::shared_ptr<const GarmentCatalogue> readCatalogue(const std::string& scenesFolder);

  // The catalogue's styles sold to `sex`, cut or sewn, in the catalogue's order.
  static std::vector<const CatalogueStyle*> styles(const GarmentCatalogue& catalogue, Sex sex);
  // `name` as a style the service dresses on a body of `sex`, or the refusal naming
  // `parameter` and `value` with what is accepted.
  static std::variant<const CatalogueStyle*, ParameterError> style(const GarmentCatalogue& catalogue, Sex sex,
                                                                   const std::string& name,
                                                                   const std::string& parameter,
                                                                   const std::string& value);
  // "dress, skirt, pencil": the styles for `sex`, for messages.
  static std::string styleNames(const GarmentCatalogue& catalogue, Sex sex);

  // A body of `sex` when no measurement is given: the chart's M (its middle size without
  // one), to the mm.
  static BodyMeasures defaultBody(const GarmentCatalogue& catalogue, Sex sex);
  // The garment a body of `sex` wears when no outfit is given: the first style sold to it,
  // in the default body's size. {style, size}.
  static std::pair<std::string, std::string> defaultGarment(const GarmentCatalogue& catalogue, Sex sex);

  // GET /api/catalogue's part for made bodies: each style with its sizes per sex, its
  // colours; the chart's sizes with their bodies; the measurements' ranges and defaults
  // per sex; the poses.
  static nlohmann::json toJson(const GarmentCatalogue& catalogue);
};

}  // namespace figment::serve

#include "sim/garment/GarmentStyle.h"

#include <cmath>

#include "sim/garment/FlaredSkirt.h"
#include "sim/garment/PencilSkirt.h"
#include "sim/garment/StrapDress.h"
#include "sim/garment/TShirt.h"

namespace figment {

namespace {

// A radial stand-off that adds `girth` (m) to a convex outline's perimeter.
double standOff(double girth) {
  return girth / (2.0 * M_PI);
}

}  // namespace

const std::vector<GarmentStyle>& garmentStyles() {
  // Constants only: the ease each style is designed with (docs/sizes.md).
  static const std::vector<GarmentStyle> styles = {
      {"dress",
       StyleKind::StrapDress,
       {0.06, 0.06, 0.06},
       "jersey",
       "strap dress, straight from the bust to the hips, A-line below",
       {"bust", "underbust", "waist", "hips", "shoulders"}},
      {"skirt",
       StyleKind::FlaredSkirt,
       {0.0, 0.03, 0.03},
       "cotton",
       "flared skirt, hanging from the waist",
       {"waist"},
       false},
      {"tshirt",
       StyleKind::TShirt,
       {0.10, 0.10, 0.10},
       "jersey",
       "T-shirt with short sleeves",
       {"bust", "underbust", "waist", "shoulders", "upper arms"}},
      {"pencil",
       StyleKind::PencilSkirt,
       {0.0, 0.02, 0.04},
       "cotton",
       "straight (pencil) skirt, fitted",
       {"waist", "hips", "thighs"}},
  };
  return styles;
}

const GarmentStyle* findStyle(const std::string& name) {
  for (const GarmentStyle& style : garmentStyles())
    if (name == style.name) return &style;
  return nullptr;
}

std::string styleNames() {
  std::string names;
  for (const GarmentStyle& style : garmentStyles()) names += (names.empty() ? "" : ", ") + std::string(style.name);
  return names;
}

TriangleMesh cutGarment(const GarmentStyle& style, const TriangleMesh& body) {
  switch (style.kind) {
    case StyleKind::StrapDress: {
      StrapDressOptions options;
      options.clearance = standOff(style.ease.bust);
      return makeStrapDress(body, options).mesh;
    }
    case StyleKind::FlaredSkirt: {
      FlaredSkirtOptions options;
      options.waistClearance = standOff(style.ease.waist);
      return makeFlaredSkirt(body, options).mesh;
    }
    case StyleKind::TShirt: {
      TShirtOptions options;
      options.ease = standOff(style.ease.bust);
      return makeTShirt(body, options).mesh;
    }
    case StyleKind::PencilSkirt: {
      PencilSkirtOptions options;
      options.waistEase = style.ease.waist;
      options.hipEase = style.ease.hip;
      return makePencilSkirt(body, options).mesh;
    }
  }
  return {};
}

}  // namespace figment

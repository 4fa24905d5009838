#pragma once
// figment-view's --size and --view values.

#include <optional>
#include <string>

namespace figment::viewer {

struct ImageSize {
  int width = 800;
  int height = 600;
};

// Where the camera looks from, in degrees: azimuth about +y from +z (front, 0) towards
// +x (right, 90), elevation above the horizontal plane, in (-90, 90).
struct ViewDirection {
  double azimuth = 0.0;
  double elevation = 0.0;
};

// "WxH", each 1..16384 pixels; nullopt otherwise.
std::optional<ImageSize> parseImageSize(const std::string& text);

// "front" (0,0), "right" (90,0), "back" (180,0), "left" (270,0), or "AZ,EL" in degrees
// with EL in (-90, 90) (each [+-]digits[.digits]); nullopt otherwise, also for a
// number too large for a double.
std::optional<ViewDirection> parseViewDirection(const std::string& text);

}  // namespace figment::viewer

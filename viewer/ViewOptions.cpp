#include "viewer/ViewOptions.h"

#include <cmath>
#include <regex>

namespace figment::viewer {

std::optional<ImageSize> parseImageSize(const std::string& text) {
  static const std::regex pattern(R"(^(\d{1,5})[xX](\d{1,5})$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return std::nullopt;
  const ImageSize size{std::stoi(m[1]), std::stoi(m[2])};
  constexpr int kMaxPixels = 16384;  // Coin renders larger images in tiles; keep it sane
  if (size.width < 1 || size.height < 1 || size.width > kMaxPixels || size.height > kMaxPixels)
    return std::nullopt;
  return size;
}

std::optional<ViewDirection> parseViewDirection(const std::string& text) {
  if (text == "front") return ViewDirection{0.0, 0.0};
  if (text == "right") return ViewDirection{90.0, 0.0};
  if (text == "back") return ViewDirection{180.0, 0.0};
  if (text == "left") return ViewDirection{270.0, 0.0};
  static const std::regex pattern(R"(^\s*([-+]?\d+(\.\d*)?|[-+]?\.\d+)\s*,\s*([-+]?\d+(\.\d*)?|[-+]?\.\d+)\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return std::nullopt;
  const ViewDirection view{std::stod(m[1]), std::stod(m[3])};
  // Straight up or down the camera's "up" (+y) is undefined.
  if (!std::isfinite(view.azimuth) || !(std::abs(view.elevation) < 90.0)) return std::nullopt;
  return view;
}

}  // namespace figment::viewer

#include "viewer/ViewOptions.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <regex>
#include <string_view>

namespace figment::viewer {

std::optional<ImageSize> parseImageSize(const std::string& text) {
  static const std::regex pattern(R"(^(\d{1,5})[xX](\d{1,5})$)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) return std::nullopt;
  const ImageSize size{std::stoi(m[1]), std::stoi(m[2])};
  constexpr int kMaxPixels = 16384;  // Coin renders larger images in tiles; keep it sane
  if (size.width < 1 || size.height < 1 || size.width > kMaxPixels || size.height > kMaxPixels) return std::nullopt;
  return size;
}

namespace {

// A decimal number as figment-view takes an angle: [+-] digits [. digits] or [+-] . digits,
// with spaces around it; nullopt otherwise, and for one too large for a double (a
// 400-digit azimuth), where std::stod would throw.
std::optional<double> parseDecimal(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  const bool negative = !text.empty() && text.front() == '-';
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) text.remove_prefix(1);
  const size_t point = text.find('.');
  const std::string_view whole = text.substr(0, point);
  const std::string_view fraction = point == std::string_view::npos ? std::string_view() : text.substr(point + 1);
  const auto digits = [](std::string_view part) {
    return std::all_of(part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
  };
  if (whole.empty() && fraction.empty()) return std::nullopt;
  if (!digits(whole) || !digits(fraction)) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return negative ? -value : value;
}

}  // namespace

std::optional<ViewDirection> parseViewDirection(const std::string& text) {
  if (text == "front") return ViewDirection{0.0, 0.0};
  if (text == "right") return ViewDirection{90.0, 0.0};
  if (text == "back") return ViewDirection{180.0, 0.0};
  if (text == "left") return ViewDirection{270.0, 0.0};
  const size_t comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const std::optional<double> azimuth = parseDecimal(std::string_view(text).substr(0, comma));
  const std::optional<double> elevation = parseDecimal(std::string_view(text).substr(comma + 1));
  if (!azimuth || !elevation) return std::nullopt;
  // Straight up or down the camera's "up" (+y) is undefined.
  if (!std::isfinite(*azimuth) || !(std::abs(*elevation) < 90.0)) return std::nullopt;
  return ViewDirection{*azimuth, *elevation};
}

std::optional<int> parseTurntableCount(const std::string& text) {
  if (text.empty() || text.size() > 4) return std::nullopt;
  int count = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (count < 1 || count > kMaxTurntableViews) return std::nullopt;
  return count;
}

std::vector<ViewDirection> turntableViews(int count, const std::optional<ViewDirection>& start) {
  const ViewDirection first = start.value_or(ViewDirection{});
  std::vector<ViewDirection> views;
  for (int i = 0; i < count; ++i) views.push_back({first.azimuth + 360.0 * i / count, first.elevation});
  return views;
}

std::optional<std::vector<double>> parseFrameTimes(const std::string& text) {
  const size_t first = text.find(':');
  const size_t second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos || text.find(':', second + 1) != std::string::npos) return std::nullopt;
  const std::optional<double> begin = parseDecimal(std::string_view(text).substr(0, first));
  const std::optional<double> end = parseDecimal(std::string_view(text).substr(first + 1, second - first - 1));
  const std::string countText = text.substr(second + 1);
  int count = 0;
  const auto [countEnd, error] = std::from_chars(countText.data(), countText.data() + countText.size(), count);
  if (!begin || !end || countText.empty() || error != std::errc() || countEnd != countText.data() + countText.size())
    return std::nullopt;
  // Simulated times: from the start (0) on, forwards, and not so far that the steps to
  // get there could not be counted (ClothEngine bounds maxTime / timeStep anyway).
  constexpr double kMaxSeconds = 1e6;
  if (!std::isfinite(*begin) || !std::isfinite(*end) || *begin < 0.0 || *end < *begin || *end > kMaxSeconds)
    return std::nullopt;
  if (count < 1 || count > kMaxFrames) return std::nullopt;
  std::vector<double> times;
  for (int i = 0; i < count; ++i) times.push_back(count == 1 ? *begin : *begin + (*end - *begin) * i / (count - 1));
  return times;
}

}  // namespace figment::viewer

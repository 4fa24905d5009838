#pragma once
// figment-view's --size, --view, --turntable and --frames values, read into the scene
// session's own types (session/SessionOptions.h).

#include <optional>
#include <string>
#include <vector>

#include "session/SessionOptions.h"

namespace figment::viewer {

using session::ImageSize;
using session::ViewDirection;

// "WxH", each 1..16384 pixels; nullopt otherwise.
std::optional<ImageSize> parseImageSize(const std::string& text);

// "front" (0,0), "right" (90,0), "back" (180,0), "left" (270,0), or "AZ,EL" in degrees
// with EL in (-90, 90) (each [+-]digits[.digits]); nullopt otherwise, also for a
// number too large for a double.
std::optional<ViewDirection> parseViewDirection(const std::string& text);

// --turntable N: a whole number of views, 1 to kMaxTurntableViews ("8"; no sign, no
// spaces); nullopt otherwise.
constexpr int kMaxTurntableViews = 3600;
std::optional<int> parseTurntableCount(const std::string& text);

// N views around the body: azimuths start, start + 360/N, ..., at start's elevation
// (front at elevation 0 when no start is given).
std::vector<ViewDirection> turntableViews(int count, const std::optional<ViewDirection>& start);

// --frames T0:T1:N: N simulated times from T0 to T1 s, both included, evenly spaced
// (T0 alone when N = 1), with 0 <= T0 <= T1 and 1 <= N <= kMaxFrames; each time a
// decimal number as an angle is ("0.5", "2", ".25"). Nullopt otherwise.
constexpr int kMaxFrames = 10000;
std::optional<std::vector<double>> parseFrameTimes(const std::string& text);

}  // namespace figment::viewer

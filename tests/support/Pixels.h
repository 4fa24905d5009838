#pragma once
// Pixel counting by flat colour, for the rendering tests (BASE_COLOR lighting, no
// antialiasing: every pixel of a shape has its colour exactly).

#include <cstdlib>
#include <vector>

namespace figment::test {

struct Rgb {
  int r, g, b;
};

// An RGB image, 3 bytes per pixel.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;

  bool is(int pixel, Rgb c, int tolerance = 8) const {
    const unsigned char* p = &rgb[3 * pixel];
    return std::abs(p[0] - c.r) <= tolerance && std::abs(p[1] - c.g) <= tolerance && std::abs(p[2] - c.b) <= tolerance;
  }
  int count(Rgb c) const {
    int n = 0;
    for (int i = 0; i < width * height; ++i) n += is(i, c);
    return n;
  }
  // Pixels of colour c where `mask` is true.
  int countWithin(Rgb c, const std::vector<bool>& mask) const {
    int n = 0;
    for (int i = 0; i < width * height; ++i) n += mask[i] && is(i, c);
    return n;
  }
  std::vector<bool> where(Rgb c) const {
    std::vector<bool> mask(width * height);
    for (int i = 0; i < width * height; ++i) mask[i] = is(i, c);
    return mask;
  }
};

inline constexpr Rgb kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kYellow{255, 255, 0}, kMagenta{255, 0, 255};

}  // namespace figment::test

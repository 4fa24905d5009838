#pragma once
// A PNG file's decoded pixels, for tests that compare pictures by what they show, never
// by file bytes (metadata would make equal pictures differ, or differing ones agree).

#include <Inventor/SbImage.h>
#include <Inventor/SoDB.h>

#include <string>

#include "support/Pixels.h"

namespace figment::test {

// The image in `path` as RGB (alpha dropped, grey expanded); width 0 when unreadable.
inline Image readPng(const std::string& path) {
  SoDB::init();  // SbImage reads through Coin's image loaders
  SbImage file;
  if (!file.readFile(path.c_str())) return {};
  SbVec2s size;
  int components = 0;
  const unsigned char* data = file.getValue(size, components);
  if (!data || components < 1) return {};
  Image image{size[0], size[1], {}};
  image.rgb.reserve(size_t(3) * size[0] * size[1]);
  for (int i = 0; i < size[0] * size[1]; ++i) {
    const unsigned char* p = data + size_t(i) * components;
    for (int c = 0; c < 3; ++c) image.rgb.push_back(components >= 3 ? p[c] : p[0]);
  }
  return image;
}

// Pixels whose colour differs between two images of one size (-1 when the sizes differ).
inline int differingPixels(const Image& a, const Image& b, int tolerance = 8) {
  if (a.width != b.width || a.height != b.height || a.width == 0) return -1;
  int n = 0;
  for (int i = 0; i < a.width * a.height; ++i)
    n += !a.is(i, Rgb{b.rgb[3 * i], b.rgb[3 * i + 1], b.rgb[3 * i + 2]}, tolerance);
  return n;
}

}  // namespace figment::test

#pragma once
// PNG files whose bytes are their pixels: no name, time or program in the metadata, so
// the same picture always gives the same file and a digest of the file can name it
// (Coin's writer, through simage, stores the file's own name in a text chunk).

#include <string>

namespace figment {

// An 8-bit RGB image, 3 bytes a pixel, rows bottom first (OpenGL's order, as
// SoOffscreenRenderer::getBuffer gives them).
struct RgbImageView {
  int width = 0, height = 0;
  const unsigned char* bottomRowFirst = nullptr;
};

// Writes `image` to `path` as an 8-bit RGB PNG, top row first as PNG stores rows,
// atomically (writeAtomically): `path` exists only when the whole image was written.
// Returns "" on success, else why not (the system's reason where there is one).
std::string writePng(const std::string& path, const RgbImageView& image);

// The same PNG bytes in memory (a service answers with them, no file between): `bytes`
// holds the file writePng would write. Returns "" on success, else why not.
std::string encodePng(const RgbImageView& image, std::string& bytes);

}  // namespace figment

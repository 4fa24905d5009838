#pragma once
// Renders a staged scene off-screen and writes it as a PNG image.

#include <Inventor/SbColor.h>

#include <memory>
#include <string>
#include <vector>

#include "session/SessionOptions.h"

class SoNode;
class SoOffscreenRenderer;

namespace figment::session {

class SceneRenderer {
 public:
  // Images of `size`; with `supersample` k > 1 each is drawn at k times the width and
  // the height and box-filtered down (each pixel the mean of its k x k samples), so
  // edges are anti-aliased. k is lowered where k times the size would pass the largest
  // image the off-screen context draws in one piece, 16384 pixels a side with OSMesa
  // (supersample() says what it is).
  explicit SceneRenderer(const ImageSize& size, int supersample = 1);
  ~SceneRenderer();

  // The neutral grey behind the scene.
  static SbColor background();
  // The largest k in [1, wanted] at which `size` times k is drawn in one piece: both
  // sides within `largest` (the off-screen context's limit, SoOffscreenRenderer's
  // maximum resolution) and Coin's 16-bit viewport.
  static int supersampleWithin(const ImageSize& size, int wanted, int largestWidth, int largestHeight);

  // Renders `root` (holding its camera and lights, see stageScene) through the OSMesa
  // context initHeadless() registered. The stencil rule decides, in the render, which
  // StencilSeparators write the stencil and which ClothingLayers are masked for the
  // root's camera; `keepStencilFields` switches it off for this render, so their own
  // writeStencil and masked values decide (figment::keepStencilFields). Returns "" on
  // success, else the error.
  std::string render(SoNode* root, bool keepStencilFields = false);
  // The last image: RGB, 3 bytes per pixel, bottom row first (OpenGL's order).
  const unsigned char* pixels() const;
  const ImageSize& size() const { return size_; }
  // The factor the images are drawn at (1: no supersampling).
  int supersample() const { return supersample_; }
  // Writes the last image as PNG (figment::writePng: the same pixels give the same
  // bytes), atomically: `path` exists only when the whole image was written. Returns ""
  // on success, else the error.
  std::string writePng(const std::string& path) const;

 private:
  ImageSize size_;
  int supersample_ = 1;
  std::unique_ptr<SoOffscreenRenderer> renderer_;
  std::vector<unsigned char> filtered_;  // the image box-filtered down (supersample_ > 1)
  bool rendered_ = false;
};

}  // namespace figment::session

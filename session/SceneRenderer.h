#pragma once
// Renders a staged scene off-screen and writes it as a PNG image.

#include <Inventor/SbColor.h>

#include <memory>
#include <string>

#include "session/SessionOptions.h"

class SoNode;
class SoOffscreenRenderer;

namespace figment::session {

class SceneRenderer {
 public:
  explicit SceneRenderer(const ImageSize& size);
  ~SceneRenderer();

  // The neutral grey behind the scene.
  static SbColor background();

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
  // Writes the last image as PNG (figment::writePng: the same pixels give the same
  // bytes), atomically: `path` exists only when the whole image was written. Returns ""
  // on success, else the error.
  std::string writePng(const std::string& path) const;

 private:
  ImageSize size_;
  std::unique_ptr<SoOffscreenRenderer> renderer_;
  bool rendered_ = false;
};

}  // namespace figment::session

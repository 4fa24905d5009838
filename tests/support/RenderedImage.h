#pragma once
// One picture of a staged scene as a test::Image: the SceneRenderer's render and the copy
// of its pixels that the pixel-counting tests each wrote out before. The render's error
// (empty when it drew) fails the calling test; without pixels the image is left empty.

#include <Inventor/nodes/SoNode.h>
#include <gtest/gtest.h>

#include "session/SceneRenderer.h"
#include "support/Pixels.h"

namespace figment::test {

inline Image renderedImage(SoNode* root, const figment::session::ImageSize& size, bool keepStencilFields = false) {
  figment::session::SceneRenderer renderer(size);
  EXPECT_EQ(renderer.render(root, keepStencilFields), "");
  Image image{size.width, size.height, {}};
  if (renderer.pixels()) image.rgb.assign(renderer.pixels(), renderer.pixels() + 3 * size.width * size.height);
  return image;
}

}  // namespace figment::test

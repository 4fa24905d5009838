#include "session/SceneRenderer.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/actions/SoGLRenderAction.h>

#include "io/PngFile.h"
#include "nodes/render/StencilRuleElement.h"

namespace figment::session {

SceneRenderer::SceneRenderer(const ImageSize& size)
    : size_(size),
      renderer_(std::make_unique<SoOffscreenRenderer>(SbViewportRegion(short(size.width), short(size.height)))) {
  renderer_->setComponents(SoOffscreenRenderer::RGB);
  renderer_->setBackgroundColor(background());
}

SceneRenderer::~SceneRenderer() = default;

SbColor SceneRenderer::background() {
  return SbColor(0.8f, 0.8f, 0.8f);
}

std::string SceneRenderer::render(SoNode* root, bool keepStencilFields) {
  // The stencil rule runs inside the render (StencilSeparator, ClothingLayer); it is
  // only switched off here.
  SoGLRenderAction& action = *renderer_->getGLRenderAction();
  if (keepStencilFields) figment::keepStencilFields(action, true);
  rendered_ = renderer_->render(root) == TRUE;
  if (keepStencilFields) figment::keepStencilFields(action, false);
  return rendered_ ? "" : "could not render: no off-screen OpenGL context";
}

const unsigned char* SceneRenderer::pixels() const {
  return rendered_ ? renderer_->getBuffer() : nullptr;
}

std::string SceneRenderer::writePng(const std::string& path) const {
  if (!rendered_) return "nothing rendered";
  return figment::writePng(path, {size_.width, size_.height, renderer_->getBuffer()});
}

}  // namespace figment::session

#include "viewer/SceneRenderer.h"

#include "nodes/render/GLStencilElement.h"
#include "nodes/render/StencilRule.h"
#include "io/AtomicFile.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoCamera.h>

namespace figment::viewer {

SceneRenderer::SceneRenderer(const ImageSize& size)
    : size_(size),
      renderer_(std::make_unique<SoOffscreenRenderer>(SbViewportRegion(short(size.width), short(size.height)))) {
  renderer_->setComponents(SoOffscreenRenderer::RGB);
  renderer_->setBackgroundColor(background());
  clearStencilEachFrame(*renderer_->getGLRenderAction());
}

SceneRenderer::~SceneRenderer() = default;

SbColor SceneRenderer::background() { return SbColor(0.8f, 0.8f, 0.8f); }

namespace {
// The view volume of the first camera under `root`, for this viewport; false if none.
bool cameraView(SoNode* root, const SbViewportRegion& viewport, SbViewVolume& view) {
  SoSearchAction search;
  search.setType(SoCamera::getClassTypeId());
  search.apply(root);
  if (!search.getPath()) return false;
  view = static_cast<SoCamera*>(search.getPath()->getTail())->getViewVolume(viewport.getViewportAspectRatio());
  return true;
}
}  // namespace

std::string SceneRenderer::render(SoNode* root, bool keepStencilFields) {
  const SbViewportRegion& viewport = renderer_->getViewportRegion();
  SbViewVolume view;
  if (!keepStencilFields && cameraView(root, viewport, view)) applyStencilRule(root, viewport, view);
  rendered_ = renderer_->render(root) == TRUE;
  return rendered_ ? "" : "could not render: no off-screen OpenGL context";
}

const unsigned char* SceneRenderer::pixels() const { return rendered_ ? renderer_->getBuffer() : nullptr; }

std::string SceneRenderer::writePng(const std::string& path) const {
  if (!rendered_) return "nothing rendered";
  if (!renderer_->isWriteSupported("png")) return "cannot write PNG: Coin has no simage library";
  return writeAtomically(path, [this](const std::string& temporary) -> std::string {
    return renderer_->writeToFile(SbString(temporary.c_str()), "png") ? "" : "cannot write the image";
  });
}

}  // namespace figment::viewer

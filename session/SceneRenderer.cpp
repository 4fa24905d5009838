#include "session/SceneRenderer.h"

#include <GL/gl.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoOffscreenRenderer.h>
#include <Inventor/actions/SoGLRenderAction.h>

#include <algorithm>
#include <limits>

#include "io/PngFile.h"
#include "nodes/render/StencilRuleElement.h"

namespace figment::session {

namespace {

// Each pixel of `out` (RGB, width x height) the mean, rounded, of its k x k samples in
// `in` (RGB, k times as wide and high; both bottom row first).
void boxFilter(const unsigned char* in, int width, int height, int k, std::vector<unsigned char>& out) {
  out.assign(size_t(3) * width * height, 0);
  const int inWidth = width * k, samples = k * k;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int sy = 0; sy < k; ++sy) {
          const unsigned char* row = in + 3 * (size_t(y * k + sy) * inWidth + size_t(x) * k) + c;
          for (int sx = 0; sx < k; ++sx) sum += row[3 * sx];
        }
        out[3 * (size_t(y) * width + x) + c] = static_cast<unsigned char>((sum + samples / 2) / samples);
      }
}

// Lines and points a scene draws at GL's width (Mannequin's volume wireframes) keep
// their width in the final image: k samples wide before the filter. A width a scene
// sets itself (DrawStyle) is Coin's to send, and is not scaled.
void widenLines(void* k, SoGLRenderAction*) {
  const auto factor = static_cast<GLfloat>(*static_cast<int*>(k));
  glLineWidth(factor);
  glPointSize(factor);
}

// The largest side OSMesa draws (OSMESA_MAX_WIDTH and _HEIGHT, and GL_MAX_VIEWPORT_DIMS,
// on llvmpipe): Coin's SoOffscreenRenderer::getMaximumResolution() says 32767 with the
// OSMesa context, and past 16384 Coin would split the image into tiles.
constexpr int kOsmesaLargestSide = 16384;

}  // namespace

SceneRenderer::SceneRenderer(const ImageSize& size, int supersample) : size_(size) {
  const SbVec2s largest = SoOffscreenRenderer::getMaximumResolution();
  supersample_ = supersampleWithin(size, supersample, std::min<int>(largest[0], kOsmesaLargestSide),
                                   std::min<int>(largest[1], kOsmesaLargestSide));
  const SbViewportRegion region(short(size.width * supersample_), short(size.height * supersample_));
  renderer_ = std::make_unique<SoOffscreenRenderer>(region);
  renderer_->setComponents(SoOffscreenRenderer::RGB);
  renderer_->setBackgroundColor(background());
  if (supersample_ > 1) renderer_->getGLRenderAction()->addPreRenderCallback(widenLines, &supersample_);
}

SceneRenderer::~SceneRenderer() = default;

SbColor SceneRenderer::background() {
  return SbColor(0.8f, 0.8f, 0.8f);
}

int SceneRenderer::supersampleWithin(const ImageSize& size, int wanted, int largestWidth, int largestHeight) {
  // A maximum Coin could not find (0) leaves the viewport's own limit.
  const int shortMax = std::numeric_limits<short>::max();
  const int widthLimit = largestWidth > 0 ? std::min(largestWidth, shortMax) : shortMax;
  const int heightLimit = largestHeight > 0 ? std::min(largestHeight, shortMax) : shortMax;
  const int fits = std::min(widthLimit / std::max(size.width, 1), heightLimit / std::max(size.height, 1));
  return std::max(1, std::min(wanted, fits));
}

std::string SceneRenderer::render(SoNode* root, bool keepStencilFields) {
  // The stencil rule runs inside the render (StencilSeparator, ClothingLayer); it is
  // only switched off here.
  SoGLRenderAction& action = *renderer_->getGLRenderAction();
  if (keepStencilFields) figment::keepStencilFields(action, true);
  rendered_ = renderer_->render(root) == TRUE;
  if (keepStencilFields) figment::keepStencilFields(action, false);
  if (rendered_ && supersample_ > 1)
    boxFilter(renderer_->getBuffer(), size_.width, size_.height, supersample_, filtered_);
  return rendered_ ? "" : "could not render: no off-screen OpenGL context";
}

const unsigned char* SceneRenderer::pixels() const {
  if (!rendered_) return nullptr;
  return supersample_ > 1 ? filtered_.data() : renderer_->getBuffer();
}

std::string SceneRenderer::writePng(const std::string& path) const {
  if (!rendered_) return "nothing rendered";
  return figment::writePng(path, {size_.width, size_.height, pixels()});
}

}  // namespace figment::session

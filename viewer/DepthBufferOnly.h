#pragma once
// The scene as the depth buffer alone draws it (paper Fig. 5.2a): FIGMENT's hybrid
// nodes swapped for their plain counterparts, and back.

class SoNode;

#include <vector>

namespace figment::viewer {

// Finds every ClothingLayer, DepthSortedGroup and StencilSeparator under `root` and
// pairs it with a plain stand-in (IndexedFaceSet with the same coordIndex and
// vertexProperty, Group and Separator with the same children; for a layer with a display
// mesh, displaySubdivision > 0, a Callback through which the layer draws that mesh with the
// depth buffer alone, ClothingLayer::GLRenderPlain). use(true) puts the
// stand-ins in the scene, use(false) the hybrid nodes again. Pieces of a
// DepthSortedGroup are expected to be Separators (a ClothingLayer directly inside a
// swapped group is not swapped in the stand-in).
class DepthBufferOnly {
 public:
  explicit DepthBufferOnly(SoNode* root);
  ~DepthBufferOnly();
  DepthBufferOnly(const DepthBufferOnly&) = delete;
  DepthBufferOnly& operator=(const DepthBufferOnly&) = delete;

  void use(bool depthBufferOnly);

 private:
  struct Swap;
  std::vector<Swap> swaps_;
};

}  // namespace figment::viewer

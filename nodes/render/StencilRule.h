#pragma once
// The rule that decides, for one view, which StencilSeparators write the stencil and
// which ClothingLayers are masked (paper §5 leaves it open: "the boolean fields are
// set" when the viewpoint changes). It runs inside rendering: the nodes ask it for the
// view being rendered, and the answer is render state, never written into fields.

#include <Inventor/SbViewVolume.h>
#include <Inventor/SbViewportRegion.h>

#include <vector>

class SoGLRenderAction;
class SoNode;

namespace figment {

struct StencilDecision {
  std::vector<const SoNode*> writers;  // StencilSeparators that write the stencil
  std::vector<const SoNode*> masked;   // ClothingLayers that are masked by it

  bool writes(const SoNode* separator) const;
  bool masks(const SoNode* layer) const;
};

// For the camera `view`, a StencilSeparator under `root` writes the stencil when it
// lies in front of a ClothingLayer: their screen rectangles overlap, and the centre of
// the separator's bounding box lies in the front half of the layer's depth along the
// viewing direction (nearer than halfway from the layer's centre to its nearest point,
// that of the ellipsoid inscribed in its bounding box): a forearm across a shirt, the
// near arm seen from the side or obliquely from behind; not a torso the garment
// encloses, nor a part behind the garment. Every ClothingLayer that such a
// separator lies in front of is masked. Changes nothing in the scene.
StencilDecision decideStencil(SoNode* root, const SbViewportRegion& viewport, const SbViewVolume& view);

// decideStencil() for the render `action` is doing now: the scene it was applied to,
// the view volume and viewport of the camera traversed so far. Kept in the action's
// state (StencilDecisionElement) while neither the scene (its node id), the view nor
// the viewport changes, so a frame decides once and a still camera re-draws without
// deciding again; each action keeps its own.
const StencilDecision& decideStencil(SoGLRenderAction* action);

}  // namespace figment

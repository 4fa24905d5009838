#pragma once
// A render request's scene, built in code from FIGMENT's nodes (never from text a
// request holds): the lights of its preset; the default mannequin sized by the request's
// measurements (Catalogue::bodyFactors) and posed; its skin; and each garment of the
// outfit, innermost first, draped by a ClothEngine on the mannequin and on the draped
// surfaces of the garments under it, as scenes/outfit-layers.iv drapes its two. The
// same nodes and settings as the shipped scenes, so the same request drapes as a scene
// file would.

#include "serve/RenderRequest.h"

class SoSeparator;

namespace figment::serve {

class Wardrobe;

class OutfitScene {
 public:
  // The scene's root, not referenced (SceneSession::adopt takes it).
  static SoSeparator* build(const RenderRequest& request, const Wardrobe& wardrobe);
};

}  // namespace figment::serve

#include "nodes/ClothingLayer.h"

SO_NODE_SOURCE(ClothingLayer);

void ClothingLayer::initClass() {
  if (classTypeId != SoType::badType()) return;
  SO_NODE_INIT_CLASS(ClothingLayer, SoIndexedFaceSet, "IndexedFaceSet");
}

ClothingLayer::ClothingLayer() {
  SO_NODE_CONSTRUCTOR(ClothingLayer);
  SO_NODE_ADD_FIELD(masked, (FALSE));
}

ClothingLayer::~ClothingLayer() = default;

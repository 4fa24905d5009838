#include "nodes/Init.h"

#include "nodes/ClothEngine.h"
#include "nodes/ClothingLayer.h"
#include "nodes/DepthSortedGroup.h"
#include "nodes/MeshFile.h"
#include "nodes/StencilSeparator.h"

#include <Inventor/SoDB.h>

namespace figment {

void init() {
  SoDB::init();  // a no-op when Coin is already initialised
  // Each initClass() returns at once when its class is already registered, so a
  // second init(), or a class Coin loaded on its own through libX.so, is harmless.
  MeshFile::initClass();
  ClothingLayer::initClass();
  ClothEngine::initClass();
  DepthSortedGroup::initClass();
  StencilSeparator::initClass();
}

}  // namespace figment

#include "nodes/Init.h"

#include "nodes/CapsuleVolume.h"
#include "nodes/ClothEngine.h"
#include "nodes/ClothingLayer.h"
#include "nodes/DepthSortedGroup.h"
#include "nodes/ExactVolume.h"
#include "nodes/Mannequin.h"
#include "nodes/MannequinSkin.h"
#include "nodes/MeshFile.h"
#include "nodes/RadialDepthVolume.h"
#include "nodes/SkeletonJoints.h"
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
  SkeletonJoints::initClass();
  CapsuleVolume::initClass();
  RadialDepthVolume::initClass();
  ExactVolume::initClass();
  Mannequin::initClass();
  MannequinSkin::initClass();
}

}  // namespace figment

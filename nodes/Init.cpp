#include "nodes/Init.h"

#include <Inventor/SoDB.h>

#include "nodes/body/CapsuleVolume.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/ExactVolume.h"
#include "nodes/body/HumanBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MannequinSkin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/body/RadialDepthVolume.h"
#include "nodes/body/SkeletonJoints.h"
#include "nodes/cloth/CatalogueGarment.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/GarmentSurface.h"
#include "nodes/cloth/SewingPattern.h"
#include "nodes/render/ClothingLayer.h"
#include "nodes/render/DepthSortedGroup.h"
#include "nodes/render/StencilSeparator.h"

namespace figment {

void init() {
  SoDB::init();  // a no-op when Coin is already initialised
  // Each initClass() returns at once when its class is already registered, so a
  // second init(), or a class Coin loaded on its own through libX.so, is harmless.
  MeshFile::initClass();
  HumanBody::initClass();
  CatalogueGarment::initClass();
  SewingPattern::initClass();
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
  GarmentSurface::initClass();
  CollisionGroup::initClass();
}

}  // namespace figment

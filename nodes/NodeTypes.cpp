#include "nodes/NodeTypes.h"

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

namespace {

// Each entry written {"Class", &Class::initClass}: nodes/CMakeLists.txt reads the names from
// that pattern, so a class added here gets its lib<Class>.so link with nothing else to edit.
constexpr NodeType kNodeTypes[] = {
    {"MeshFile", &MeshFile::initClass},
    {"HumanBody", &HumanBody::initClass},
    {"CatalogueGarment", &CatalogueGarment::initClass},
    {"SewingPattern", &SewingPattern::initClass},
    {"ClothingLayer", &ClothingLayer::initClass},
    {"ClothEngine", &ClothEngine::initClass},
    {"DepthSortedGroup", &DepthSortedGroup::initClass},
    {"StencilSeparator", &StencilSeparator::initClass},
    {"SkeletonJoints", &SkeletonJoints::initClass},
    {"CapsuleVolume", &CapsuleVolume::initClass},
    {"RadialDepthVolume", &RadialDepthVolume::initClass},
    {"ExactVolume", &ExactVolume::initClass},
    {"Mannequin", &Mannequin::initClass},
    {"MannequinSkin", &MannequinSkin::initClass},
    {"GarmentSurface", &GarmentSurface::initClass},
    {"CollisionGroup", &CollisionGroup::initClass},
};

}  // namespace

std::span<const NodeType> nodeTypes() {
  return kNodeTypes;
}

}  // namespace figment

#include "viewer/DepthBufferOnly.h"

#include "nodes/ClothingLayer.h"
#include "nodes/DepthSortedGroup.h"
#include "nodes/StencilSeparator.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

namespace figment::viewer {

struct DepthBufferOnly::Swap {
  SoGroup* parent;
  SoNode* hybrid;
  SoNode* plain;
};

namespace {

std::vector<SoPath*> pathsTo(SoNode* root, SoType type) {
  SoSearchAction search;
  search.setType(type, FALSE);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::vector<SoPath*> paths;
  for (int i = 0; i < search.getPaths().getLength(); ++i) {
    search.getPaths()[i]->ref();
    paths.push_back(search.getPaths()[i]);
  }
  return paths;
}

SoGroup* regroup(SoNode* node, SoGroup* into) {
  auto* group = static_cast<SoGroup*>(node);
  for (int i = 0; i < group->getNumChildren(); ++i) into->addChild(group->getChild(i));
  return into;
}

}  // namespace

DepthBufferOnly::DepthBufferOnly(SoNode* root) {
  auto add = [this](SoPath* path, SoNode* plain) {
    Swap s{static_cast<SoGroup*>(path->getNodeFromTail(1)), path->getTail(), plain};
    s.parent->ref(), s.hybrid->ref(), s.plain->ref();
    swaps_.push_back(s);
    path->unref();
  };
  for (SoPath* path : pathsTo(root, ClothingLayer::getClassTypeId())) {
    auto* layer = static_cast<ClothingLayer*>(path->getTail());
    auto* faces = new SoIndexedFaceSet;
    faces->coordIndex = layer->coordIndex;
    faces->vertexProperty = layer->vertexProperty.getValue();
    add(path, faces);
  }
  for (SoPath* path : pathsTo(root, DepthSortedGroup::getClassTypeId())) add(path, regroup(path->getTail(), new SoGroup));
  for (SoPath* path : pathsTo(root, StencilSeparator::getClassTypeId()))
    add(path, regroup(path->getTail(), new SoSeparator));
}

DepthBufferOnly::~DepthBufferOnly() {
  use(false);
  for (Swap& s : swaps_) s.parent->unref(), s.hybrid->unref(), s.plain->unref();
}

void DepthBufferOnly::use(bool depthBufferOnly) {
  for (Swap& s : swaps_) {
    SoNode* now = depthBufferOnly ? s.hybrid : s.plain;
    if (s.parent->findChild(now) >= 0) s.parent->replaceChild(now, depthBufferOnly ? s.plain : s.hybrid);
  }
}

}  // namespace figment::viewer

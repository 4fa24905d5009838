#include "viewer/DepthBufferOnly.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include "nodes/SceneSearch.h"
#include "nodes/render/ClothingLayer.h"
#include "nodes/render/DepthSortedGroup.h"
#include "nodes/render/StencilSeparator.h"

namespace figment::viewer {

struct DepthBufferOnly::Swap {
  SoGroup* parent;
  SoNode* hybrid;
  SoNode* plain;
};

namespace {

SoGroup* regroup(SoNode* node, SoGroup* into) {
  auto* group = static_cast<SoGroup*>(node);
  for (int i = 0; i < group->getNumChildren(); ++i) into->addChild(group->getChild(i));
  return into;
}

// A layer with a display mesh, drawn by the depth buffer alone: the layer's own plain
// drawing of its display mesh (the triangles the hybrid passes draw), bounded as the layer.
void drawPlainly(void* data, SoAction* action) {
  auto* layer = static_cast<ClothingLayer*>(data);
  if (action->isOfType(SoGLRenderAction::getClassTypeId()))
    layer->GLRenderPlain(static_cast<SoGLRenderAction*>(action));
  else if (action->isOfType(SoGetBoundingBoxAction::getClassTypeId()))
    layer->getBoundingBox(static_cast<SoGetBoundingBoxAction*>(action));
}

SoNode* plainLayer(ClothingLayer* layer) {
  if (layer->displaySubdivision.getValue() != 0) {
    auto* callback = new SoCallback;
    callback->setCallback(drawPlainly, layer);
    return callback;
  }
  auto* faces = new SoIndexedFaceSet;
  faces->coordIndex = layer->coordIndex;
  faces->vertexProperty = layer->vertexProperty.getValue();
  return faces;
}

}  // namespace

DepthBufferOnly::DepthBufferOnly(SoNode* root) {
  auto add = [this](const SoPath* path, SoNode* plain) {
    Swap s{static_cast<SoGroup*>(path->getNodeFromTail(1)), path->getTail(), plain};
    s.parent->ref(), s.hybrid->ref(), s.plain->ref();
    swaps_.push_back(s);
  };
  const SoPathList layers = findAll(root, ClothingLayer::getClassTypeId());
  for (int i = 0; i < layers.getLength(); ++i) {
    add(layers[i], plainLayer(static_cast<ClothingLayer*>(layers[i]->getTail())));
  }
  const SoPathList groups = findAll(root, DepthSortedGroup::getClassTypeId());
  for (int i = 0; i < groups.getLength(); ++i) add(groups[i], regroup(groups[i]->getTail(), new SoGroup));
  const SoPathList separators = findAll(root, StencilSeparator::getClassTypeId());
  for (int i = 0; i < separators.getLength(); ++i)
    add(separators[i], regroup(separators[i]->getTail(), new SoSeparator));
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

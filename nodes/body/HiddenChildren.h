#pragma once
// Internal to figment_nodes: nodes that draw through children of their own (a mesh
// they build), hidden from the scene, reach them the way SoFile reaches its children.

class SoAction;
class SoChildList;
class SoCoordinate3;
class SoIndexedFaceSet;

namespace figment {

// The hidden mesh such a node draws: a Separator holding an empty Coordinate3 and an
// IndexedFaceSet, appended to `children`, drawn like any shape with the current state
// (Material, ShapeHints before the node).
struct HiddenMesh {
  SoCoordinate3* coordinates = nullptr;
  SoIndexedFaceSet* faces = nullptr;
};
HiddenMesh appendHiddenMesh(SoChildList& children);

// Traverses `children` with `action`, along the action's path when it has one.
void traverseHidden(SoChildList& children, SoAction* action);

}  // namespace figment

#pragma once
// Whether each node field holds a node of the type it takes. Coin reads any node into an
// SFNode or MFNode field, and its VRML97 nodes cast what their typed fields hold without a
// check: a VRMLIndexedLineSet or VRMLPointSet whose coord is a VRMLMaterial, or a VRMLText
// whose fontStyle is one, crashed figment-view (SIGSEGV); a VRMLShape casts its appearance.

#include <string>

class SoNode;

namespace figment::guard {

// "" when every typed node field of every node linked from `root` (NodeLinks.h) holds a node
// of the type the VRML97 specification or Coin gives it (a VRMLIndexedFaceSet's coord a
// VRMLCoordinate, a VRMLShape's geometry a shape, a VertexShape's vertexProperty a
// VertexProperty, ...), else one line naming the first that does not: "VRMLText 'Label':
// fontStyle holds a VRMLMaterial, where a VRMLFontStyle belongs". Fields that take any node
// (children, a SceneTexture2's scene) are not checked. Walks each node once, without recursion.
std::string firstMistypedNodeField(const SoNode* root);

}  // namespace figment::guard

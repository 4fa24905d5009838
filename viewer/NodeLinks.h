#pragma once
// The nodes a node links to. Groups hold children; other nodes hold nodes in SFNode and
// MFNode fields (a VRMLText's fontStyle, a VertexShape's vertexProperty, a SceneTexture2's
// scene), which Coin's destructors release as recursively as children. VRML nodes show
// theirs both ways (a VRMLShape's children are its appearance and geometry).

#include <vector>

class SoNode;
class SoField;

namespace figment::viewer {

// `node`'s children, each as often as it holds it, then the nodes its SFNode and MFNode
// fields hold that are not among them (each once). A connected field is evaluated.
std::vector<SoNode*> linkedNodes(const SoNode& node);

// `node`'s SFNode and MFNode fields.
std::vector<SoField*> nodeFields(const SoNode& node);

}  // namespace figment::viewer

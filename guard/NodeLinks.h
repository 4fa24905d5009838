#pragma once
// The nodes a node links to. Groups hold children; other nodes hold nodes in SFNode and
// MFNode fields (a VRMLText's fontStyle, a VertexShape's vertexProperty, a SceneTexture2's
// scene), which Coin's destructors release as recursively as children. VRML nodes show
// theirs both ways (a VRMLShape's children are its appearance and geometry).

#include <functional>
#include <string>
#include <vector>

class SoNode;
class SoField;

namespace figment::guard {

// `node`'s children, each as often as it holds it, then the nodes its SFNode and MFNode
// fields hold that are not among them (each once). A connected field is evaluated.
std::vector<SoNode*> linkedNodes(const SoNode& node);

// Calls `visit` on each node linked from `root`, `root` first, each once, in scene order (a
// node before what it links to), without recursion; stops at the first non-empty result
// and returns it.
std::string firstProblemAmongLinkedNodes(const SoNode* root, const std::function<std::string(const SoNode&)>& visit);

// "VRMLText 'Label'": the node's type, and its name when it has one.
std::string describeNode(const SoNode& node);

// `node`'s SFNode and MFNode fields.
std::vector<SoField*> nodeFields(const SoNode& node);

}  // namespace figment::guard

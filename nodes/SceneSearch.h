#pragma once
// Finding nodes of a type, and the engines that drape, in a scene graph: every scene
// search FIGMENT needs, in one place.

#include <Inventor/SoType.h>
#include <Inventor/lists/SoPathList.h>

#include <vector>

class ClothEngine;
class SoNode;
class SoPath;

namespace figment {

// Paths from `root` to every node of `type` (or derived from it), including nodes under
// switches that are off at the moment. The list holds references to its paths.
SoPathList findAll(SoNode* root, SoType type);

// The last node of `path` (or the one `fromTail` places before it), hidden children
// included; null when the path is shorter. What Coin's idiom
// static_cast<SoFullPath*>(path)->getNodeFromTail(fromTail) gives, without that downcast: a
// search's path is an SoPath, never an SoFullPath, so the cast is undefined behaviour (UBSan
// stops on it: "downcast of address ... which does not point to an object of type SoFullPath").
SoNode* fullTail(const SoPath* path, int fromTail = 0);

// The ClothEngines that feed the scene under `root`, in scene order, each once: engines
// connected to a field of any node in the graph (inactive Switch children included),
// of nodes held in node fields, and engines feeding those engines' inputs.
std::vector<ClothEngine*> findClothEngines(SoNode* root);

}  // namespace figment

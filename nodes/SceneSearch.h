#pragma once
// Finding nodes of a type in a scene graph, the way FIGMENT's tools need it.

#include <Inventor/SoType.h>
#include <Inventor/lists/SoPathList.h>

class SoNode;

namespace figment {

// Paths from `root` to every node of `type` (or derived from it), including nodes under
// switches that are off at the moment. The list holds references to its paths.
SoPathList findAll(SoNode* root, SoType type);

}  // namespace figment

#pragma once
// What a study's garments collide with, by name: "scene" (as the scene says), "exact"
// (the triangles of the scene's Mannequin body), or a volumes file (.iv, as figment-fit
// writes it) that replaces the Mannequin's children on a copy of it (same body, pose
// and sizes).

#include <Inventor/nodes/SoNode.h>

#include <string>

namespace figment::bench {

// The body node for `choice`, or null for "scene" and on failure (then `error` says why,
// naming the choice).
SoNode* bodyFor(const std::string& choice, SoNode* root, std::string& error);

}  // namespace figment::bench

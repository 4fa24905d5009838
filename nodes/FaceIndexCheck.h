#pragma once
// Whether the indexed shapes of a scene index only the coordinates they have: Coin
// trusts coordIndex, and one index of 2147483647 has it allocate 2^31 normals
// (std::bad_alloc) or read far past the coordinates.

#include <string>

class SoNode;

namespace figment {

// Every indexed shape drawn under `root` (ClothingLayer, IndexedFaceSet, IndexedLineSet,
// ..., under the Switch children drawn now), its coordIndex checked against the
// coordinates it uses (its vertexProperty's, else the current Coordinate3 or a
// ClothEngine's positions feeding it): each entry a vertex, or the -1 that ends a face.
// Returns "" when all are, else one line naming the first bad one, e.g.
// "ClothingLayer 'Shirt': coordIndex[3] = 2147483647 is not a vertex: the coordinates
// have 4 points". Reading the coordinates evaluates the engines that feed them: check
// after draping.
std::string firstFaceIndexError(SoNode* root);

}  // namespace figment

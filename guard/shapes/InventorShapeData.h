#pragma once
// Whether an Inventor shape reads only the data it has. Coin trusts the indices and counts
// of its shapes: a materialIndex, normalIndex or textureCoordIndex entry past the materials,
// normals or texture coordinates, or a FaceSet or TriangleStripSet drawing more vertices
// than there are, a MarkerSet's markerIndex past Coin's markers, each crashed figment-view
// (SIGSEGV).

#include <string>

class SoIndexedShape;
class SoNonIndexedShape;
class SoState;

namespace figment::guard::shapes {

// "" when every index of `shape`, drawn with `state` (its vertexProperty's data where it has
// them, as Coin draws it), is an entry of the data it indexes: coordIndex the coordinates;
// materialIndex, normalIndex and textureCoordIndex their data where the binding indexes them
// (PER_..._INDEXED), and coordIndex those data too where a per-vertex indexed binding has no
// index of its own; an IndexedMarkerSet's markerIndex Coin's markers. Else one line naming
// node, field, entry and value.
std::string indexedShapeProblem(const SoIndexedShape& shape, SoState* state);

// "" when a FaceSet, LineSet, TriangleStripSet, QuadMesh or PointSet, drawn with `state`,
// draws no more vertices from startIndex than the coordinates have, and a MarkerSet's
// markerIndex names Coin's markers; else one line naming node, fields and counts.
std::string countedShapeProblem(const SoNonIndexedShape& shape, SoState* state);

}  // namespace figment::guard::shapes

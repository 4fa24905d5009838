#pragma once
// Whether the shapes of a scene index and count only the data they have: Coin trusts
// them. One coordIndex of 2147483647 had it allocate 2^31 normals (std::bad_alloc); a
// materialIndex, normalIndex or textureCoordIndex past its data, a FaceSet counting more
// vertices than the coordinates, a VRMLIndexedFaceSet's colorIndex past its colors each
// crashed figment-view (SIGSEGV). The checks themselves are in guard/shapes/. Part of the
// guard's public entry (guard/Guard.h): what a program runs before it draws a scene.

#include <string>

class SoNode;

namespace figment::guard {

// Every shape drawn under `root` (under the Switch children drawn now) checked against the
// data it uses: an indexed shape (ClothingLayer, IndexedFaceSet, IndexedLineSet, ...) its
// coordIndex against its coordinates (its vertexProperty's, else the current Coordinate3 or
// a ClothEngine's positions feeding it), each entry a vertex or the -1 that ends a face, and
// its other indices against the data their bindings index; a counted shape (FaceSet,
// TriangleStripSet, ...) its counts against the coordinates; a NURBS shape its control points
// and knots; a VRML97 shape its indices and counts against its own data nodes
// (shapes/InventorShapeData.h, shapes/NurbsShapeData.h, shapes/VrmlShapeData.h).
// Returns "" when all are, else one line naming the first bad one, e.g.
// "ClothingLayer 'Shirt': coordIndex[3] = 2147483647 is not a vertex: the coordinates
// have 4 points". Reading the coordinates evaluates the engines that feed them: check
// after draping.
std::string checkShapes(SoNode* root);

}  // namespace figment::guard

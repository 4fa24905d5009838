#pragma once
// A body mesh cut into the parts of its skeleton (sim/body/Skeleton.h): the inputs of the
// collision volumes (§3; shaped by sim/volumes).
//
// The cut, per triangle (by its centroid c and outward face normal n):
//   1. the nearest bone among those the triangle faces away from, n . (c - q) >= 0 with
//      q the bone's nearest point to c (a torso flank facing the arm is not the arm's,
//      an inner thigh facing the other leg is not that leg's); the nearest bone when it
//      faces none;
//   2. each part keeps the largest connected piece of its triangles (connected through
//      shared vertex positions); every smaller piece joins the part that most of its
//      neighbouring triangles belong to (repeated until nothing moves).

#include <string>
#include <vector>

#include "sim/body/Skeleton.h"

namespace figment {

struct PartMesh {
  std::string name;
  TriangleMesh mesh;  // the body's triangles assigned to this part (see above)
  Vec3 from, to;      // the bone
};

// With `borderRings` > 0 each part also keeps that many rings of its neighbours'
// triangles round its cut (triangles sharing a vertex with it, ring by ring): an exact
// part's surface then overlaps the next part's, so no seam is left open between them.
std::vector<PartMesh> splitIntoParts(const TriangleMesh& body, const Skeleton& skeleton, int borderRings = 0);

// The part index (into skeleton.parts) of each triangle of `body`, as described above.
std::vector<int> assignTriangles(const TriangleMesh& body, const Skeleton& skeleton);

// The part of each vertex of `body`: the part most of its triangles belong to (ties: the
// lower index); -1 for a vertex no triangle uses. With triangleParts from
// assignTriangles, the vertices skin with the parts whose volumes were shaped to them.
std::vector<int> vertexParts(const TriangleMesh& body, const std::vector<int>& triangleParts, size_t partCount);

}  // namespace figment

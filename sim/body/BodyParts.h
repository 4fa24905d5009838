#pragma once
// A body mesh cut into the parts of its skeleton (sim/body/Skeleton.h), and a radial depth
// volume fitted along each part's bone: the inputs of the collision volumes (§3).
//
// The cut, per triangle (by its centroid c and outward face normal n):
//   1. the nearest bone among those the triangle faces away from, n . (c - q) >= 0 with
//      q the bone's nearest point to c (a torso flank facing the arm is not the arm's,
//      an inner thigh facing the other leg is not that leg's); the nearest bone when it
//      faces none;
//   2. each part keeps the largest connected piece of its triangles (connected through
//      shared vertex positions); every smaller piece joins the part that most of its
//      neighbouring triangles belong to (repeated until nothing moves).

#include "sim/collision/RadialDepth.h"
#include "sim/body/Skeleton.h"

#include <string>
#include <vector>

namespace figment {

struct PartMesh {
  std::string name;
  TriangleMesh mesh;  // the body's triangles assigned to this part (see above)
  Vec3 from, to;      // the bone
};

std::vector<PartMesh> splitIntoParts(const TriangleMesh& body, const Skeleton& skeleton);

// The part index (into skeleton.parts) of each triangle of `body`, as described above.
std::vector<int> assignTriangles(const TriangleMesh& body, const Skeleton& skeleton);

// The part of each vertex of `body`: the part most of its triangles belong to (ties: the
// lower index); -1 for a vertex no triangle uses. With triangleParts from
// assignTriangles, the vertices skin with the parts whose volumes were fitted to them.
std::vector<int> vertexParts(const TriangleMesh& body, const std::vector<int>& triangleParts, size_t partCount);

// A radial depth volume on the best axis found: the best of three (the bone; the bone's
// direction through the part's centroid; the part's principal axis nearest the bone's
// direction, through the centroid) by radialGapEstimate, then the genetic search
// (sim/fitting/AxisSearch.h) from it; each volume lengthened to span every vertex of the part,
// with sections about `sectionSpacing` (m) apart and K = `harmonics`
// (fitRadialDepthToPoints on the part's vertices and triangle centroids).
RadialDepth fitRadialPart(const PartMesh& part, int harmonics, double sectionSpacing);

// A cheap estimate of the mean gap from `vertices` to `volume`: the radial shortfall
// r(s, a) - rho of each, at most its distance to the nearer cap (m).
double radialGapEstimate(const RadialDepth& volume, const std::vector<Vec3>& vertices);

}  // namespace figment

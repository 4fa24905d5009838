#pragma once
// Where a surface passes through itself: pairs of its triangles that cross. What the made
// bodies are checked for (issue 30: no two parts of the skin intersect that do not in the
// base mesh: an arm into the torso, the thighs into each other at large hip girths).
// Formulas and sources at the top of SelfIntersections.cpp.

#include <utility>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Whether triangles (a0, a1, a2) and (b0, b1, b2) cross: an edge of one passes through the
// other's interior. Touching (a vertex or edge lying exactly in the other's plane) and
// coplanar overlap do not count: a closed surface's neighbouring faces touch without
// crossing.
bool trianglesCross(const Vec3& a0, const Vec3& a1, const Vec3& a2, const Vec3& b0, const Vec3& b1, const Vec3& b2);

using TrianglePair = std::pair<int, int>;  // (lower index, higher index)

// Every pair of triangles of `mesh` that share no vertex and cross, sorted; found through a
// bounding-volume hierarchy (sim/collision/TriangleBvh.h) of the mesh's triangles.
std::vector<TrianglePair> selfIntersections(const TriangleMesh& mesh);

// The labels (lower, higher) of the crossing pairs whose two triangles carry different labels
// (`triangleLabel`, one per triangle of the mesh `pairs` come from: its body parts), sorted,
// once each: which parts cross which. Throws std::out_of_range for a triangle it has no
// label for.
std::vector<std::pair<int, int>> crossingLabels(const std::vector<TrianglePair>& pairs,
                                                const std::vector<int>& triangleLabel);

}  // namespace figment

#pragma once
// Midpoint subdivision: each triangle into four, a new vertex at the middle of each
// edge. The surface does not move (the new vertices lie on the old edges), so a
// garment can be made finer without changing its shape: the garment-size study and
// the T-shirt above the skin's triangle count start from it.

#include "sim/core/TriangleMesh.h"

namespace figment {

// The old vertices keep their indices; the edge midpoints follow, numbered in the order
// the triangles first meet their edges. Triangle t becomes 4t..4t+3 (the three corners,
// then the middle one), each wound as t was.
TriangleMesh subdivided(const TriangleMesh& mesh);

}  // namespace figment

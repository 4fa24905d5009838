#pragma once

#include "sim/core/TriangleMesh.h"

namespace figment {

// Joins rings of vertices into an open tube: ring r's vertex c sits at r * columns + c, each
// ring closes on itself, and every quad between two rings becomes two triangles wound the
// same way, so a skirt made ring by ring is one consistently oriented piece. Adds
// 2 * (rings - 1) * columns triangles.
void addRingTubeTriangles(TriangleMesh& mesh, int rings, int columns);

}  // namespace figment

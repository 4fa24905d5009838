#include "sim/garment/RingTube.h"

namespace figment {

void addRingTubeTriangles(TriangleMesh& mesh, int rings, int columns) {
  for (int row = 0; row + 1 < rings; ++row)
    for (int column = 0; column < columns; ++column) {
      const int a = row * columns + column, b = row * columns + (column + 1) % columns;
      const int below = a + columns, belowNext = b + columns;
      mesh.triangles.push_back({a, b, below});
      mesh.triangles.push_back({b, belowNext, below});
    }
}

}  // namespace figment

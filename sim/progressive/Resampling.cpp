#include "sim/progressive/Resampling.h"

#include <stdexcept>
#include <string>

#include "sim/core/Subdivision.h"
#include "sim/progressive/Decimation.h"

namespace figment {

TriangleMesh resampled(const TriangleMesh& garment, int triangles, const DecimationOptions& decimation) {
  if (triangles < 1 || garment.triangles.empty())
    throw std::invalid_argument("cannot resample " + std::to_string(garment.triangles.size()) + " triangles to " +
                                std::to_string(triangles));
  TriangleMesh fine = garment;
  while (static_cast<int>(fine.triangles.size()) < triangles) fine = subdivided(fine);
  if (static_cast<int>(fine.triangles.size()) == triangles) return numberedByFirstUse(fine);
  DecimationOptions options = decimation;
  options.targetFaces = triangles;
  const ProgressiveMesh decimated = decimate(fine, options);
  std::vector<int> fullIndex;
  return numberedByFirstUse(MeshLevel(decimated).restMesh(fullIndex));
}

}  // namespace figment

#pragma once
// Where a vertex split puts its vertices in the draped garment (paper §4): from the
// current deformed neighbourhood, not from the rest coordinates. The kept vertex's
// neighbourhood gives a deformation gradient F (least squares over its ring's edges,
// rest to deformed, plus its normal so F is defined across the surface too); the
// added vertex and the kept one then sit where F carries their rest offsets:
//
//   x_added = x_kept + F (addedRest - collapsedRest),   x_kept' = x_kept + F (keptRest - collapsedRest)
//
// Both take the mean velocity of the kept vertex and its ring. Positions and velocities
// are indexed by the full garment's vertices; `level` is the level before the split.

#include <vector>

#include "sim/progressive/ProgressiveMesh.h"

namespace figment {

void placeSplit(const VertexSplit& split, const MeshLevel& level, std::vector<Vec3>& x, std::vector<Vec3>& v);

}  // namespace figment

#pragma once
// Decimation by edge collapses (paper §4): the cheapest valid collapse first
// (CollapseEnergy.h), from a priority queue updated locally (each collapse re-scores
// the edges around the vertex it kept and its neighbours; stale entries are skipped by
// their vertices' stamps), until `targetFaces` sections remain or nothing may collapse.
// The collapses, reversed, are the progressive mesh's vertex splits.

#include "sim/progressive/CollapseEnergy.h"
#include "sim/progressive/ProgressiveMesh.h"

namespace figment {

ProgressiveMesh decimate(const TriangleMesh& garment, const DecimationOptions& options);

}  // namespace figment

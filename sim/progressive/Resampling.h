#pragma once
// A garment at a chosen number of sections: split by midpoint subdivision
// (sim/core/Subdivision.h) until it has at least that many, then decimated
// (Decimation.h) back down to it. Coarser than the garment is decimation alone. The
// garment-size study drapes one garment at many sizes this way, the T-shirt goes above
// the skin's triangle count with it.

#include "sim/core/TriangleMesh.h"
#include "sim/progressive/CollapseEnergy.h"

namespace figment {

// The garment with `triangles` sections (one fewer where the last collapse on a
// boundary edge removes one), vertices numbered as the triangles first use them.
// `decimation` weighs the collapses (its targetFaces is `triangles`): a larger
// perimeterWeight keeps more of the openings' vertices where they curve.
// Throws std::invalid_argument when `triangles` < 1 or the garment has none.
TriangleMesh resampled(const TriangleMesh& garment, int triangles, const DecimationOptions& decimation = {});

}  // namespace figment

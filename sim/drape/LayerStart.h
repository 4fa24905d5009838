#pragma once
// Where a garment starts when it is put on over garments already draped (the paper's
// Figure 6.3: the dress over the T-shirt). Each garment is cut round the body alone, so an
// outer one's cut shape lies partly inside the inner one's drape (a quarter of the dress's
// nodes under the T-shirt), and its first steps would push those nodes out to whichever
// side of the thin inner surface is nearest. Instead the drape starts over it: each node
// inside the layers beneath, or within the clearance of them, is moved out along their
// normal to the clearance, where the contacts hold it from the first step (started at
// twice the clearance, the Figure 6.3 dress was still moving at 0.027 m/s after 12 s; at
// the clearance it rests after 3.35 s), and the moves are spread to the nodes round them,
// fading over a few rings (so the cloth starts smooth, not dented). The garment's rest shape
// stays its cut shape; only where it starts changes.

#include <vector>

#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"

namespace figment {

struct LayerStart {
  std::vector<Vec3> positions;  // one per garment node
  int moved = 0;                // nodes that were inside or within the reach of the layers beneath
  double largestMove = 0.0;     // m, of any node
};

// The start of `garment` over `beneath` (the layers under it, without the body), with the
// drape's `clearance` (m, > 0). Looks `kSearch` into the layers for nodes inside them.
LayerStart startOverLayers(const TriangleMesh& garment, const Collider& beneath, double clearance);
inline constexpr double kLayerStartSearch = 0.05;  // m

}  // namespace figment

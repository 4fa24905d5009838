#pragma once
// A sewing pattern cut into cloth: every panel triangulated in its own plane, its nodes
// placed around the body as the pattern says, and the node pairs that its stitches will
// pull together. Nothing is sewn yet: the panels are separate pieces of one mesh.
//
// The rest shape of the cloth is the flat panel: `flat` holds each node's panel
// coordinates (m), which are also the garment's texture coordinates. Each panel's
// placement is rigid, so until it is sewn a panel's placed triangles have the shapes
// of its flat ones.

#include <array>
#include <string>
#include <vector>

#include "sim/pattern/SewingPattern.h"

namespace figment {

struct UnsewnGarment {
  // Every panel's nodes, placed (m, the body frame), and its triangles, counter-clockwise
  // seen from the fabric's right side (outside the garment).
  TriangleMesh placed;
  std::vector<Vec2> flat;    // per node: its panel coordinates (m)
  std::vector<int> panelOf;  // per node: the index of its panel in the pattern
  std::vector<std::string> panelNames;
  // Per seam: the two nodes a stitch pulls together, and the stitch it belongs to (its
  // index in the pattern). A corner node may be in several seams (a corner where two
  // stitches meet); every node of an edge in a stitch is in at least one, but for a dart's
  // tip, which its stitch pairs with itself (no seam).
  std::vector<std::array<int, 2>> seams;
  std::vector<int> seamStitch;
};

}  // namespace figment

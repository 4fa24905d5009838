#pragma once
// The order and depth mode in which a ClothingLayer draws its facets (paper §5): every
// facet sorted by its centre's depth, far to near, and marked as facing the viewer or
// away. Geometry only (no GL), so it is tested on its own.

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <cstdint>
#include <vector>

namespace figment {

struct ViewPoint {
  bool perspective = true;
  SbVec3f eye;             // perspective: the eye, in the facets' (object) frame
  SbVec3f direction;       // orthographic: the viewing direction, in the object frame
  SbMatrix toCamera;       // object frame -> camera frame (camera looks down -z)
  bool clockwise = false;  // vertex ordering: CLOCKWISE flips which side is the front
  // A facet counts as facing the viewer unless it faces away "substantially" (paper §5):
  // by more than this cosine between its normal and the line to the eye. Nearly edge-on
  // facets at a layer's silhouette then cover what an inner layer puts there.
  float edgeOnCosine = 0.05f;
};

// What a facet is, whatever the view: computed once per change of the coordinates.
struct FacetGeometry {
  int32_t firstIndex;  // into coordIndex
  int32_t corners;
  SbVec3f centre;
  SbVec3f normal;  // Newell's normal (counter-clockwise front), not normalised
};

// Facets of `coordIndex` (polygons ended by -1 or the end) with every index in
// [0, pointCount) and at least three corners; others are skipped.
std::vector<FacetGeometry> describeFacets(const SbVec3f* points, int pointCount, const int32_t* coordIndex,
                                          int indexCount);

// Which way round a layer's facets are wound, judged from its shape: a garment wraps
// what it covers (a body, an inner layer), so its outside is the side that faces away
// from its middle. Counter-clockwise when the facets' counter-clockwise normals point
// away from the area-weighted centre of the facets, taken over all of them (each
// weighted by its area): outward by at least a third of the sum of the parts, clockwise
// when they point inward by as much, undecided in between (a flat or barely curved
// sheet, whose sides cannot be told apart this way).
enum class Winding { COUNTERCLOCKWISE, CLOCKWISE, UNDECIDED };
Winding outsideWinding(const std::vector<FacetGeometry>& facets);

struct OrderedFacet {
  int32_t firstIndex;  // into coordIndex: the facet's first corner
  int32_t corners;     // how many corners it has (>= 3)
  bool facesViewer;    // the front faces the eye: drawn over what lies beneath
};

// The facets far to near for `view`, each marked facing the viewer or away.
std::vector<OrderedFacet> orderFacets(const std::vector<FacetGeometry>& facets, const ViewPoint& view);
// Both steps at once.
std::vector<OrderedFacet> orderFacets(const SbVec3f* points, int pointCount, const int32_t* coordIndex, int indexCount,
                                      const ViewPoint& view);

}  // namespace figment

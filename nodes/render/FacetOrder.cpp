#include "nodes/render/FacetOrder.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "guard/CoordIndexFaces.h"

namespace figment {

std::vector<FacetGeometry> describeFacets(const SbVec3f* points, int pointCount, const int32_t* coordIndex,
                                          int indexCount) {
  std::vector<FacetGeometry> facets;
  for (const guard::CoordIndexFace& face : guard::coordIndexFaces(coordIndex, indexCount)) {
    const int corners = face.corners();
    if (corners < 3 || !guard::cornersBelow(face, coordIndex, pointCount)) continue;
    // Newell's normal: right for any planar polygon and robust for nearly planar ones.
    SbVec3f normal(0, 0, 0), centre(0, 0, 0);
    for (int k = 0; k < corners; ++k) {
      const SbVec3f& a = points[coordIndex[face.first + k]];
      const SbVec3f& b = points[coordIndex[face.first + (k + 1) % corners]];
      normal += SbVec3f((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1]));
      centre += a;
    }
    facets.push_back({face.first, corners, centre / static_cast<float>(corners), normal});
  }
  return facets;
}

Winding outsideWinding(const std::vector<FacetGeometry>& facets) {
  // Newell's normal is twice the facet's area along its normal: the weights come with it.
  SbVec3f middle(0, 0, 0);
  float area = 0.0f;
  for (const FacetGeometry& f : facets) {
    middle += f.normal.length() * f.centre;
    area += f.normal.length();
  }
  if (!(area > 0.0f)) return Winding::UNDECIDED;
  middle /= area;
  double outward = 0.0, magnitude = 0.0;  // sums over the facets of n . (c - middle), and of |n . (c - middle)|
  for (const FacetGeometry& f : facets) {
    const double part = f.normal.dot(f.centre - middle);
    outward += part;
    magnitude += std::abs(part);
  }
  constexpr double kDecisive = 1.0 / 3.0;
  if (outward > kDecisive * magnitude) return Winding::COUNTERCLOCKWISE;
  if (outward < -kDecisive * magnitude) return Winding::CLOCKWISE;
  return Winding::UNDECIDED;
}

std::vector<OrderedFacet> orderFacets(const std::vector<FacetGeometry>& facets, const ViewPoint& view) {
  std::vector<float> depth(facets.size());  // camera-frame z of each centre (more negative = farther)
  std::vector<OrderedFacet> marked(facets.size());
  for (size_t i = 0; i < facets.size(); ++i) {
    const FacetGeometry& f = facets[i];
    const SbVec3f normal = view.clockwise ? -f.normal : f.normal;
    const SbVec3f towardsEye = view.perspective ? view.eye - f.centre : -view.direction;
    const float cosine = normal.dot(towardsEye) / std::max(normal.length() * towardsEye.length(), 1e-30f);
    marked[i] = {f.firstIndex, f.corners, cosine > -view.edgeOnCosine};
    SbVec3f inCamera;
    view.toCamera.multVecMatrix(f.centre, inCamera);
    depth[i] = inCamera[2];
  }
  std::vector<int> order(facets.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  std::vector<OrderedFacet> sorted;
  sorted.reserve(facets.size());
  for (int i : order) sorted.push_back(marked[i]);
  return sorted;
}

std::vector<OrderedFacet> orderFacets(const SbVec3f* points, int pointCount, const int32_t* coordIndex, int indexCount,
                                      const ViewPoint& view) {
  return orderFacets(describeFacets(points, pointCount, coordIndex, indexCount), view);
}

}  // namespace figment

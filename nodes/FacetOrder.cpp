#include "nodes/FacetOrder.h"

#include <algorithm>
#include <numeric>

namespace figment {

std::vector<OrderedFacet> orderFacets(const SbVec3f* points, int pointCount, const int32_t* coordIndex,
                                      int indexCount, const ViewPoint& view) {
  std::vector<OrderedFacet> facets;
  std::vector<float> depth;  // camera-frame z of each facet's centre (more negative = farther)
  int start = 0;
  while (start < indexCount) {
    int end = start;
    bool valid = true;
    while (end < indexCount && coordIndex[end] >= 0) valid &= coordIndex[end] < pointCount, ++end;
    const int corners = end - start;
    if (valid && corners >= 3) {
      // Newell's normal: right for any planar polygon and robust for nearly planar ones.
      SbVec3f normal(0, 0, 0), centre(0, 0, 0);
      for (int k = 0; k < corners; ++k) {
        const SbVec3f& a = points[coordIndex[start + k]];
        const SbVec3f& b = points[coordIndex[start + (k + 1) % corners]];
        normal += SbVec3f((a[1] - b[1]) * (a[2] + b[2]), (a[2] - b[2]) * (a[0] + b[0]), (a[0] - b[0]) * (a[1] + b[1]));
        centre += a;
      }
      centre /= static_cast<float>(corners);
      if (view.clockwise) normal.negate();
      const SbVec3f towardsEye = view.perspective ? view.eye - centre : -view.direction;
      SbVec3f inCamera;
      view.toCamera.multVecMatrix(centre, inCamera);
      const float cosine = normal.dot(towardsEye) / std::max(normal.length() * towardsEye.length(), 1e-30f);
      facets.push_back({start, corners, cosine > -view.edgeOnCosine});
      depth.push_back(inCamera[2]);
    }
    start = end + 1;
  }
  std::vector<int> order(facets.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return depth[a] < depth[b]; });
  std::vector<OrderedFacet> sorted;
  sorted.reserve(facets.size());
  for (int i : order) sorted.push_back(facets[i]);
  return sorted;
}

}  // namespace figment

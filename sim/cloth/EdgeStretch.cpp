#include "sim/cloth/EdgeStretch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace figment {

EdgeStretch::EdgeStretch(const RestShape& rest) {
  if (const TriangleMesh* mesh = rest.mesh()) {
    *this = EdgeStretch(*mesh);
    return;
  }
  // Flat pieces: each edge's rest length as the sections that have it were cut, the mean
  // where two sections sewn along it differ.
  std::map<std::pair<int, int>, std::pair<double, int>> sums;
  for (size_t s = 0; s < rest.triangles().size(); ++s) {
    const Triangle& t = rest.triangles()[s];
    for (int k = 0; k < 3; ++k) {
      auto& [sum, count] = sums[std::minmax(t[k], t[(k + 1) % 3])];
      sum += (rest.corners(s)[(k + 1) % 3] - rest.corners(s)[k]).norm();
      ++count;
    }
  }
  for (const auto& [edge, sum] : sums) {
    const double length = sum.first / sum.second;
    if (!(length > 0.0)) continue;
    edges_.push_back({edge.first, edge.second});
    restLengths_.push_back(length);
  }
}

EdgeStretch::EdgeStretch(const TriangleMesh& rest) {
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * rest.triangles.size());
  for (const Triangle& t : rest.triangles)
    for (int k = 0; k < 3; ++k) edges.emplace_back(std::minmax(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  for (const auto& [a, b] : edges) {
    const double length = (rest.vertices[a] - rest.vertices[b]).norm();
    if (!(length > 0.0)) continue;
    edges_.push_back({a, b});
    restLengths_.push_back(length);
  }
}

double EdgeStretch::stretch(size_t edge, const std::vector<Vec3>& x) const {
  const auto [a, b] = edges_[edge];
  return (x[a] - x[b]).norm() / restLengths_[edge];
}

double EdgeStretch::largest(const std::vector<Vec3>& x) const {
  double most = edges_.empty() ? 1.0 : 0.0;
  for (size_t e = 0; e < edges_.size(); ++e) most = std::max(most, stretch(e, x));
  return most;
}

bool EdgeStretch::jumped(const std::vector<Vec3>& before, const std::vector<Vec3>& after, double bound,
                         double growth) const {
  for (size_t e = 0; e < edges_.size(); ++e) {
    const double now = stretch(e, after);
    if (!std::isfinite(now) || (now > bound && now - stretch(e, before) > growth)) return true;
  }
  return false;
}

}  // namespace figment

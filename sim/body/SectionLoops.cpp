// Plane sections as connected pieces. Based on:
// - edge crossings: an edge (p, q) whose signed distances d_p, d_q to the plane have
//   opposite signs meets it at p + d_p / (d_p - d_q) (q - p);
// - union-find (Tarjan 1975) over the crossed edges: a crossed triangle has exactly two
//   crossed edges and joins them, so the pieces are the connected components.

#include "sim/body/SectionLoops.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <unordered_map>

namespace figment {

namespace {

struct Crossings {
  std::unordered_map<std::uint64_t, int> edgeIndex;  // edge (lo, hi) -> crossing number
  std::vector<Vec3> points;
  std::vector<int> parent;  // union-find over crossings

  int find(int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  int crossing(int a, int b, const Vec3& pa, const Vec3& pb, double da, double db) {
    const std::uint64_t key = (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
    const auto [it, inserted] = edgeIndex.emplace(key, int(points.size()));
    if (inserted) {
      // the same point from either triangle: computed from the lower-numbered end
      const bool aFirst = a < b;
      const Vec3& p = aFirst ? pa : pb;
      const Vec3& q = aFirst ? pb : pa;
      const double dp = aFirst ? da : db, dq = aFirst ? db : da;
      points.push_back(p + dp / (dp - dq) * (q - p));
      parent.push_back(it->second);
    }
    return it->second;
  }
  void addTriangle(const TriangleMesh& mesh, const Triangle& t, const double d[3]) {
    int found[2], n = 0;
    for (int e = 0; e < 3 && n < 2; ++e) {
      const int i = e, j = (e + 1) % 3;
      if ((d[i] >= 0) == (d[j] >= 0)) continue;
      found[n++] = crossing(t[i], t[j], mesh.vertices[t[i]], mesh.vertices[t[j]], d[i], d[j]);
    }
    if (n == 2) parent[find(found[0])] = find(found[1]);
  }
  std::vector<SectionLoop> loops() {
    std::unordered_map<int, int> loopOf;
    std::vector<SectionLoop> result;
    for (int i = 0; i < int(points.size()); ++i) {
      const auto [it, inserted] = loopOf.emplace(find(i), int(result.size()));
      if (inserted) result.emplace_back();
      SectionLoop& loop = result[it->second];
      loop.points.push_back(points[i]);
      loop.bounds.extend(points[i]);
    }
    return result;
  }
};

}  // namespace

Vec3 SectionLoop::centroid() const {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return points.empty() ? sum : Vec3(sum / double(points.size()));
}

std::vector<SectionLoop> sectionLoops(const TriangleMesh& mesh, const Vec3& point, const Vec3& normal) {
  if (normal.squaredNorm() == 0) throw std::invalid_argument("sectionLoops: normal = 0");
  Crossings crossings;
  for (const Triangle& t : mesh.triangles) {
    const double d[3] = {(mesh.vertices[t[0]] - point).dot(normal), (mesh.vertices[t[1]] - point).dot(normal),
                         (mesh.vertices[t[2]] - point).dot(normal)};
    crossings.addTriangle(mesh, t, d);
  }
  return crossings.loops();
}

HorizontalSections::HorizontalSections(const TriangleMesh& mesh) : mesh_(mesh) {
  std::vector<double> low(mesh.triangles.size());
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const Triangle& t = mesh.triangles[i];
    const double y0 = mesh.vertices[t[0]].y(), y1 = mesh.vertices[t[1]].y(), y2 = mesh.vertices[t[2]].y();
    low[i] = std::min({y0, y1, y2});
    tallest_ = std::max(tallest_, std::max({y0, y1, y2}) - low[i]);
  }
  order_.resize(low.size());
  std::iota(order_.begin(), order_.end(), 0);
  std::sort(order_.begin(), order_.end(), [&](int a, int b) { return low[a] < low[b]; });
  lowY_.resize(low.size());
  for (size_t i = 0; i < order_.size(); ++i) lowY_[i] = low[order_[i]];
}

std::vector<SectionLoop> HorizontalSections::at(double height) const {
  // only triangles whose lowest vertex lies within the tallest span below `height` can cross it
  const auto first = std::lower_bound(lowY_.begin(), lowY_.end(), height - tallest_) - lowY_.begin();
  const auto last = std::upper_bound(lowY_.begin(), lowY_.end(), height) - lowY_.begin();
  Crossings crossings;
  for (auto k = first; k < last; ++k) {
    const Triangle& t = mesh_.triangles[order_[k]];
    const double d[3] = {mesh_.vertices[t[0]].y() - height, mesh_.vertices[t[1]].y() - height,
                         mesh_.vertices[t[2]].y() - height};
    crossings.addTriangle(mesh_, t, d);
  }
  return crossings.loops();
}

}  // namespace figment

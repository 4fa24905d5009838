// Plane sections as connected pieces. Based on:
// - edge crossings: an edge (p, q) whose signed distances d_p, d_q to the plane have
//   opposite signs meets it at p + d_p / (d_p - d_q) (q - p);
// - union-find (Tarjan 1975) over the crossed edges: a crossed triangle has exactly two
//   crossed edges and joins them, so the pieces are the connected components.

#include "sim/body/SectionLoops.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace figment {

namespace {

// The crossed edges of the triangles added, then the pieces: each crossed edge is one
// crossing (shared by its two triangles), found by sorting the edges' keys rather than
// hashing them (a section has a few hundred: no table to build and free per level).
class Crossings {
 public:
  void addTriangle(const TriangleMesh& mesh, const Triangle& t, const double d[3]) {
    int n = 0;
    for (int e = 0; e < 3 && n < 2; ++e) {
      const int i = e, j = (e + 1) % 3;
      if ((d[i] >= 0) == (d[j] >= 0)) continue;
      edges_.push_back({key(t[i], t[j]), point(t[i], t[j], mesh.vertices[t[i]], mesh.vertices[t[j]], d[i], d[j])});
      ++n;
    }
    if (n == 1) edges_.pop_back();  // only ever 0 or 2 on a plane; kept safe
  }

  std::vector<SectionLoop> loops() {
    const size_t m = edges_.size();
    std::vector<int> order(m), crossing(m);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return edges_[a].key < edges_[b].key; });
    std::vector<Vec3> points;
    for (size_t k = 0; k < m; ++k) {
      if (k == 0 || edges_[order[k]].key != edges_[order[k - 1]].key) points.push_back(edges_[order[k]].point);
      crossing[order[k]] = int(points.size()) - 1;
    }
    parent_.resize(points.size());
    std::iota(parent_.begin(), parent_.end(), 0);
    for (size_t k = 0; k + 1 < m; k += 2) parent_[find(crossing[k])] = find(crossing[k + 1]);  // a triangle's two
    std::vector<int> loopOf(points.size(), -1);
    std::vector<SectionLoop> result;
    for (int i = 0; i < int(points.size()); ++i) {
      int& loop = loopOf[find(i)];
      if (loop < 0) loop = int(result.size()), result.emplace_back();
      result[loop].points.push_back(points[i]);
      result[loop].bounds.extend(points[i]);
    }
    return result;
  }

 private:
  struct Edge {
    std::uint64_t key;  // (lower vertex, higher vertex)
    Vec3 point;
  };
  static std::uint64_t key(int a, int b) {
    return (std::uint64_t(std::min(a, b)) << 32) | std::uint32_t(std::max(a, b));
  }
  // the same point from either triangle: computed from the lower-numbered end
  static Vec3 point(int a, int b, const Vec3& pa, const Vec3& pb, double da, double db) {
    const bool aFirst = a < b;
    const Vec3& p = aFirst ? pa : pb;
    const Vec3& q = aFirst ? pb : pa;
    const double dp = aFirst ? da : db, dq = aFirst ? db : da;
    return p + dp / (dp - dq) * (q - p);
  }
  int find(int i) {
    while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
    return i;
  }

  std::vector<Edge> edges_;  // in pairs: a triangle's two crossed edges
  std::vector<int> parent_;  // union-find over crossings
};

}  // namespace

Vec3 SectionLoop::centroid() const {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : points) sum += p;
  return points.empty() ? sum : Vec3(sum / double(points.size()));
}

std::vector<SectionLoop> sectionLoops(const TriangleMesh& mesh, const Vec3& point, const Vec3& normal) {
  if (normal.squaredNorm() == 0) throw std::invalid_argument("sectionLoops: normal = 0");
  // each vertex's distance once (not once per triangle corner): the same values, a sixth of
  // the products; the arm's measurement cuts the whole body some hundred times
  std::vector<double> distance(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) distance[v] = (mesh.vertices[v] - point).dot(normal);
  Crossings crossings;
  for (const Triangle& t : mesh.triangles) {
    const double d[3] = {distance[size_t(t[0])], distance[size_t(t[1])], distance[size_t(t[2])]};
    if ((d[0] >= 0) == (d[1] >= 0) && (d[1] >= 0) == (d[2] >= 0)) continue;
    crossings.addTriangle(mesh, t, d);
  }
  return crossings.loops();
}

HorizontalSections::HorizontalSections(const TriangleMesh& mesh) : mesh_(mesh) {
  // Each triangle in every band its height span meets (counting sort into bands): a level
  // then visits only the triangles of its band, about twice those that cross it.
  const size_t n = mesh.triangles.size();
  std::vector<double> low(n), high(n);
  double bottom = std::numeric_limits<double>::infinity(), top = -bottom;
  for (size_t i = 0; i < n; ++i) {
    const Triangle& t = mesh.triangles[i];
    const double y0 = mesh.vertices[t[0]].y(), y1 = mesh.vertices[t[1]].y(), y2 = mesh.vertices[t[2]].y();
    low[i] = std::min({y0, y1, y2});
    high[i] = std::max({y0, y1, y2});
    bottom = std::min(bottom, low[i]);
    top = std::max(top, high[i]);
  }
  if (n == 0) return;
  bottom_ = bottom;
  const size_t bands = size_t((top - bottom) / kBand) + 1;
  const auto band = [&](double y) { return std::min(bands - 1, size_t((y - bottom_) / kBand)); };
  start_.assign(bands + 1, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t b = band(low[i]); b <= band(high[i]); ++b) ++start_[b + 1];
  for (size_t b = 0; b < bands; ++b) start_[b + 1] += start_[b];
  members_.resize(size_t(start_[bands]));
  std::vector<int> next(start_.begin(), start_.end() - 1);
  for (size_t i = 0; i < n; ++i)
    for (size_t b = band(low[i]); b <= band(high[i]); ++b) members_[size_t(next[b]++)] = int(i);
}

std::vector<SectionLoop> HorizontalSections::at(double height) const {
  if (start_.empty() || !(height >= bottom_)) return {};
  const size_t b = size_t((height - bottom_) / kBand);
  if (b + 1 >= start_.size()) return {};
  Crossings crossings;
  for (int k = start_[b]; k < start_[b + 1]; ++k) {
    const Triangle& t = mesh_.triangles[size_t(members_[size_t(k)])];
    const double d[3] = {mesh_.vertices[t[0]].y() - height, mesh_.vertices[t[1]].y() - height,
                         mesh_.vertices[t[2]].y() - height};
    crossings.addTriangle(mesh_, t, d);
  }
  return crossings.loops();
}

}  // namespace figment

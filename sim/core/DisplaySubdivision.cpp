#include "sim/core/DisplaySubdivision.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "sim/core/BoundaryLoops.h"

namespace figment {

namespace {

// Each vertex to the first vertex at exactly its position.
std::vector<int> weldByPosition(const std::vector<Vec3>& positions) {
  std::map<std::tuple<double, double, double>, int> first;
  std::vector<int> weld(positions.size());
  for (size_t i = 0; i < positions.size(); ++i)
    weld[i] =
        first.try_emplace({positions[i].x(), positions[i].y(), positions[i].z()}, static_cast<int>(i)).first->second;
  return weld;
}

// Unit vertex normals, area weighted (the cross products' sum), of `triangles`.
std::vector<Vec3> vertexNormals(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
  std::vector<Vec3> normals(points.size(), Vec3::Zero());
  for (const Triangle& t : triangles) {
    const Vec3 n = (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]);
    for (int corner : t) normals[corner] += n;
  }
  for (Vec3& n : normals)
    if (n.squaredNorm() > 0.0) n.normalize();
  return normals;
}

// A boundary vertex's normal from its fan alone leans towards the surface's inside (on a
// sphere's cap by half the angle its triangles span); extrapolated instead, past its fan by
// as much as its neighbours inside the surface lie before it: 2 n - mean(n inside), where
// that stays within 30 degrees of the fan's.
void extrapolateBoundaryNormals(std::vector<Vec3>& normals, const std::vector<Triangle>& triangles,
                                const std::vector<std::vector<int>>& loops) {
  std::vector<bool> onBoundary(normals.size(), false);
  for (const std::vector<int>& loop : loops)
    for (int v : loop) onBoundary[v] = true;
  std::vector<Vec3> inside(normals.size(), Vec3::Zero());
  for (const Triangle& t : triangles)
    for (int e = 0; e < 3; ++e)
      if (onBoundary[t[e]] && !onBoundary[t[(e + 1) % 3]])
        inside[t[e]] += normals[t[(e + 1) % 3]];
      else if (onBoundary[t[(e + 1) % 3]] && !onBoundary[t[e]])
        inside[t[(e + 1) % 3]] += normals[t[e]];
  std::vector<Vec3> original = normals;
  for (size_t v = 0; v < normals.size(); ++v) {
    if (!onBoundary[v] || inside[v].squaredNorm() == 0.0) continue;
    const Vec3 outward = 2.0 * original[v] - inside[v].normalized();
    if (outward.squaredNorm() > 0.0 && outward.normalized().dot(original[v]) > std::cos(M_PI / 6.0))
      normals[v] = outward.normalized();
  }
}

// The edge's midpoint pulled towards the tangent planes at its ends (see the header), by
// at most a quarter of the edge.
Vec3 surfacePoint(const Vec3& a, const Vec3& b, const Vec3& na, const Vec3& nb) {
  const Vec3 m = 0.5 * (a + b);
  Vec3 move = 0.25 * ((a - m).dot(na) * na + (b - m).dot(nb) * nb);
  const double most = 0.25 * (b - a).norm();
  if (move.norm() > most) move *= most / move.norm();
  return m + move;
}

// Degrees between the edges into and out of a vertex.
double turning(const Vec3& before, const Vec3& at, const Vec3& after) {
  const Vec3 in = at - before, out = after - at;
  const double lengths = in.norm() * out.norm();
  if (lengths <= 0.0) return 0.0;
  return std::acos(std::clamp(in.dot(out) / lengths, -1.0, 1.0)) * 180.0 / M_PI;
}

}  // namespace

DisplaySubdivision::DisplaySubdivision(const std::vector<Triangle>& triangles, const std::vector<Vec3>& weldAt,
                                       int levels) {
  if (levels < 0) throw std::invalid_argument("DisplaySubdivision: levels must be >= 0");
  const int count = static_cast<int>(weldAt.size());
  weld_ = weldByPosition(weldAt);
  std::vector<Triangle> welded;
  for (const Triangle& t : triangles) {
    for (int corner : t)
      if (corner < 0 || corner >= count) throw std::invalid_argument("DisplaySubdivision: index out of range");
    const Triangle w{weld_[t[0]], weld_[t[1]], weld_[t[2]]};
    if (w[0] != w[1] && w[1] != w[2] && w[2] != w[0]) welded.push_back(w);
  }
  triangles_.push_back(std::move(welded));
  counts_.push_back(count);
  for (int level = 0; level < levels; ++level) {
    const std::vector<Triangle>& coarse = triangles_.back();
    std::map<std::pair<int, int>, int> index;  // an edge, either way round, to its place in `edges`
    std::vector<Edge> edges;
    auto split = [&](int a, int b) {
      const auto [it, added] = index.try_emplace(std::minmax(a, b), static_cast<int>(edges.size()));
      if (added)
        edges.push_back({a, b, true});
      else
        edges[it->second].boundary = false;  // a second triangle uses it
      return counts_.back() + it->second;
    };
    std::vector<Triangle> fine;
    fine.reserve(4 * coarse.size());
    for (const Triangle& t : coarse) {
      const int ab = split(t[0], t[1]), bc = split(t[1], t[2]), ca = split(t[2], t[0]);
      fine.insert(fine.end(), {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}});
    }
    loops_.push_back(boundaryLoops(coarse));
    counts_.push_back(counts_.back() + static_cast<int>(edges.size()));
    edges_.push_back(std::move(edges));
    triangles_.push_back(std::move(fine));
  }
}

void DisplaySubdivision::apply(const std::vector<Vec3>& positions, std::vector<Vec3>& points,
                               std::vector<Vec3>& normals) const {
  if (static_cast<int>(positions.size()) != counts_.front())
    throw std::invalid_argument("DisplaySubdivision: positions do not match the layout");
  points.assign(positions.begin(), positions.end());
  points.resize(displayVertexCount(), Vec3::Zero());
  normals = vertexNormals(points, triangles_.front());
  if (!loops_.empty()) extrapolateBoundaryNormals(normals, triangles_.front(), loops_.front());
  for (int i = 0; i < counts_.front(); ++i) normals[i] = normals[weld_[i]];
  for (size_t level = 0; level < edges_.size(); ++level) {
    // Each boundary vertex's neighbours along its loop, and whether it is a corner.
    const int before = counts_[level];
    std::vector<int> previous(before, -1), next(before, -1);
    for (const std::vector<int>& loop : loops_[level])
      for (size_t k = 0; k < loop.size() && loop.size() >= 3; ++k) {
        previous[loop[k]] = loop[(k + loop.size() - 1) % loop.size()];
        next[loop[k]] = loop[(k + 1) % loop.size()];
      }
    auto corner = [&](int v) {
      return previous[v] < 0 || turning(points[previous[v]], points[v], points[next[v]]) > kCornerDegrees;
    };
    for (size_t k = 0; k < edges_[level].size(); ++k) {
      auto [a, b, boundary] = edges_[level][k];
      const int at = before + static_cast<int>(k);
      Vec3 n = normals[a] + normals[b];
      normals[at] = n.squaredNorm() > 0.0 ? n.normalized() : normals[a];
      if (!boundary) {
        points[at] = surfacePoint(points[a], points[b], normals[a], normals[b]);
        continue;
      }
      if (next[b] == a) std::swap(a, b);  // along the loop: c, a, b, d
      if (next[a] != b || corner(a) || corner(b)) {
        points[at] = 0.5 * (points[a] + points[b]);
        continue;
      }
      points[at] = 9.0 / 16.0 * (points[a] + points[b]) - 1.0 / 16.0 * (points[previous[a]] + points[next[b]]);
    }
  }
}

}  // namespace figment

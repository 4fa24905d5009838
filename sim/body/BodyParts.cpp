#include "sim/body/BodyParts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace figment {

namespace {

// Vertex indices welded by position (texture seams split vertices that touch).
std::vector<int> weldedIndices(const std::vector<Vec3>& vertices) {
  std::map<std::array<long long, 3>, int> first;
  std::vector<int> welded(vertices.size());
  for (size_t v = 0; v < vertices.size(); ++v) {
    const std::array<long long, 3> key = {std::llround(vertices[v].x() * 1e6), std::llround(vertices[v].y() * 1e6),
                                          std::llround(vertices[v].z() * 1e6)};
    welded[v] = first.try_emplace(key, static_cast<int>(v)).first->second;
  }
  return welded;
}

// Triangles sharing a (welded) vertex with each triangle.
std::vector<std::vector<int>> triangleNeighbours(const TriangleMesh& body) {
  const std::vector<int> welded = weldedIndices(body.vertices);
  std::vector<std::vector<int>> around(body.vertices.size());
  for (size_t t = 0; t < body.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) around[welded[body.triangles[t][k]]].push_back(static_cast<int>(t));
  std::vector<std::vector<int>> neighbours(body.triangles.size());
  for (size_t t = 0; t < body.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k)
      for (int u : around[welded[body.triangles[t][k]]])
        if (u != static_cast<int>(t)) neighbours[t].push_back(u);
    std::sort(neighbours[t].begin(), neighbours[t].end());
    neighbours[t].erase(std::unique(neighbours[t].begin(), neighbours[t].end()), neighbours[t].end());
  }
  return neighbours;
}

}  // namespace

namespace {

// Step 1 of the cut: per triangle, the nearest bone it faces away from, else the nearest.
std::vector<int> nearestFacingBones(const TriangleMesh& body, const Skeleton& skeleton) {
  const size_t n = body.triangles.size(), parts = skeleton.parts.size();
  std::vector<int> owner(n, 0);
  for (size_t t = 0; t < n; ++t) {
    const Vec3 &a = body.vertices[body.triangles[t][0]], &b = body.vertices[body.triangles[t][1]],
               &c = body.vertices[body.triangles[t][2]];
    const Vec3 centroid = (a + b + c) / 3.0, normal = (b - a).cross(c - a);
    double best = std::numeric_limits<double>::infinity(), bestFacing = best;
    int nearest = 0, facing = -1;
    for (size_t k = 0; k < parts; ++k) {
      const Vec3& from = skeleton.joints[skeleton.parts[k].from].position;
      const Vec3 bone = skeleton.joints[skeleton.parts[k].to].position - from;
      const double f = std::clamp((centroid - from).dot(bone) / std::max(bone.squaredNorm(), 1e-18), 0.0, 1.0);
      const Vec3 out = centroid - (from + f * bone);
      const double d = out.squaredNorm();
      if (d < best) best = d, nearest = static_cast<int>(k);
      if (normal.dot(out) >= 0.0 && d < bestFacing) bestFacing = d, facing = static_cast<int>(k);
    }
    owner[t] = facing >= 0 ? facing : nearest;
  }
  return owner;
}

// The connected pieces of one owner each: every triangle's piece, and each piece's size.
void connectedPieces(const std::vector<int>& owner, const std::vector<std::vector<int>>& neighbours,
                     std::vector<int>& piece, std::vector<int>& pieceSize) {
  const size_t n = owner.size();
  piece.assign(n, -1), pieceSize.clear();
  for (size_t t = 0; t < n; ++t) {
    if (piece[t] >= 0) continue;
    const int id = static_cast<int>(pieceSize.size());
    std::vector<int> stack = {static_cast<int>(t)};
    piece[t] = id;
    int size = 0;
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      ++size;
      for (int w : neighbours[u])
        if (piece[w] < 0 && owner[w] == owner[u]) piece[w] = id, stack.push_back(w);
    }
    pieceSize.push_back(size);
  }
}

// Step 2, once: every piece of a part but its largest joins the part most of its
// neighbouring triangles belong to. False when no piece moved.
bool joinSmallPieces(std::vector<int>& owner, const std::vector<std::vector<int>>& neighbours, size_t parts) {
  const size_t n = owner.size();
  std::vector<int> piece, pieceSize;
  connectedPieces(owner, neighbours, piece, pieceSize);
  std::vector<int> largest(parts, -1);
  for (size_t t = 0; t < n; ++t) {
    int& l = largest[owner[t]];
    if (l < 0 || pieceSize[piece[t]] > pieceSize[l]) l = piece[t];
  }
  // Votes of each small piece's neighbours.
  std::map<int, std::vector<int>> votes;
  for (size_t t = 0; t < n; ++t) {
    if (piece[t] == largest[owner[t]]) continue;
    std::vector<int>& v = votes.try_emplace(piece[t], std::vector<int>(parts, 0)).first->second;
    for (int w : neighbours[t])
      if (piece[w] != piece[t]) ++v[owner[w]];
  }
  std::map<int, int> joins;
  for (const auto& [id, v] : votes) {
    const int to = static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
    if (v[to] > 0) joins[id] = to;
  }
  if (joins.empty()) return false;
  for (size_t t = 0; t < n; ++t)
    if (const auto j = joins.find(piece[t]); j != joins.end() && piece[t] != largest[owner[t]]) owner[t] = j->second;
  return true;
}

}  // namespace

std::vector<int> assignTriangles(const TriangleMesh& body, const Skeleton& skeleton) {
  std::vector<int> owner = nearestFacingBones(body, skeleton);
  // Islands: every piece of a part but its largest joins its neighbours' part.
  const std::vector<std::vector<int>> neighbours = triangleNeighbours(body);
  for (int pass = 0; pass < 10; ++pass)
    if (!joinSmallPieces(owner, neighbours, skeleton.parts.size())) break;
  return owner;
}

std::vector<PartMesh> splitIntoParts(const TriangleMesh& body, const Skeleton& skeleton, int borderRings) {
  const std::vector<int> owner = assignTriangles(body, skeleton);
  std::vector<std::vector<int>> trianglesAt(borderRings > 0 ? body.vertices.size() : 0);
  for (size_t t = 0; t < body.triangles.size() && borderRings > 0; ++t)
    for (int v : body.triangles[t]) trianglesAt[v].push_back(static_cast<int>(t));
  std::vector<PartMesh> parts;
  for (size_t p = 0; p < skeleton.parts.size(); ++p) {
    const BodyPart& bone = skeleton.parts[p];
    PartMesh part{bone.name, {}, skeleton.joints[bone.from].position, skeleton.joints[bone.to].position};
    std::vector<char> kept(body.triangles.size(), 0);
    for (size_t t = 0; t < body.triangles.size(); ++t) kept[t] = owner[t] == static_cast<int>(p);
    for (int ring = 0; ring < borderRings; ++ring) {
      std::vector<char> grown = kept;
      for (size_t t = 0; t < body.triangles.size(); ++t)
        if (kept[t])
          for (int v : body.triangles[t])
            for (int u : trianglesAt[v]) grown[u] = 1;
      kept = std::move(grown);
    }
    std::vector<int> map(body.vertices.size(), -1);
    for (size_t t = 0; t < body.triangles.size(); ++t) {
      if (!kept[t]) continue;
      Triangle triangle;
      for (int k = 0; k < 3; ++k) {
        const int v = body.triangles[t][k];
        if (map[v] < 0)
          map[v] = static_cast<int>(part.mesh.vertices.size()), part.mesh.vertices.push_back(body.vertices[v]);
        triangle[k] = map[v];
      }
      part.mesh.triangles.push_back(triangle);
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::vector<int> vertexParts(const TriangleMesh& body, const std::vector<int>& triangleParts, size_t partCount) {
  std::vector<std::vector<int>> votes(body.vertices.size());
  for (size_t t = 0; t < body.triangles.size(); ++t)
    for (int v : body.triangles[t]) {
      if (votes[v].empty()) votes[v].assign(partCount, 0);
      ++votes[v][triangleParts[t]];
    }
  std::vector<int> part(body.vertices.size(), -1);
  for (size_t v = 0; v < votes.size(); ++v)
    if (!votes[v].empty())
      part[v] = static_cast<int>(std::max_element(votes[v].begin(), votes[v].end()) - votes[v].begin());
  return part;
}

}  // namespace figment

#include "sim/collision/MeshCollider.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace figment {

namespace {
double cornerAngle(const Vec3& corner, const Vec3& next, const Vec3& previous) {
  const Vec3 u = next - corner, v = previous - corner;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// The moved surface's vertices, once they are as many as the shape's: checked before the
// tree is built over them (fewer were read past their end: the sanitizer job, 2026-12-03).
std::vector<Vec3> asManyAs(const TriangleMesh& shape, std::vector<Vec3> vertices) {
  if (vertices.size() != shape.vertices.size())
    throw std::invalid_argument("MeshCollider: " + std::to_string(vertices.size()) + " vertices for a surface of " +
                                std::to_string(shape.vertices.size()));
  return vertices;
}
}  // namespace

MeshCollider::MeshCollider(TriangleMesh surface, OpenEdges openEdges) : surface_(std::move(surface)), bvh_(surface_) {
  const auto& V = surface_.vertices;
  const auto& T = surface_.triangles;
  // Number the edges once: triangle edge 3t + k (its corners k, k + 1) -> edge.
  std::map<std::pair<int, int>, int> edges;
  edgeOf_.resize(3 * T.size());
  for (size_t t = 0; t < T.size(); ++t)
    for (int k = 0; k < 3; ++k)
      edgeOf_[3 * t + k] = edges.emplace(std::minmax(T[t][k], T[t][(k + 1) % 3]), int(edges.size())).first->second;
  edgeCount_ = int(edges.size());
  // Closest-point feature k of triangle t is edge (k, k+1): Edge01, Edge12, Edge20.
  if (openEdges == OpenEdges::Outside) {
    std::vector<int> faces(edgeCount_, 0);
    for (int e : edgeOf_) ++faces[e];
    openEdge_.assign(3 * T.size(), 0);
    openVertex_.assign(V.size(), 0);
    for (size_t t = 0; t < T.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        if (faces[edgeOf_[3 * t + k]] != 1) continue;
        openEdge_[3 * t + k] = 1;
        openVertex_[T[t][k]] = openVertex_[T[t][(k + 1) % 3]] = 1;
      }
  }
  computeNormals();
}

MeshCollider::MeshCollider(const MeshCollider& shape, std::vector<Vec3> vertices)
    : surface_{asManyAs(shape.surface_, std::move(vertices)), shape.surface_.triangles},
      bvh_(surface_),
      edgeOf_(shape.edgeOf_),
      edgeCount_(shape.edgeCount_),
      openEdge_(shape.openEdge_),
      openVertex_(shape.openVertex_) {
  computeNormals();
}

void MeshCollider::computeNormals() {
  const auto& V = surface_.vertices;
  const auto& T = surface_.triangles;
  faceNormals_.resize(T.size());
  vertexNormals_.assign(V.size(), Vec3::Zero());
  // Per edge, the sum of its faces' normals, in the order the triangles list them.
  std::vector<Vec3> edgeSums(edgeCount_, Vec3::Zero());
  for (size_t t = 0; t < T.size(); ++t) {
    const Vec3 &a = V[T[t][0]], &b = V[T[t][1]], &c = V[T[t][2]];
    const Vec3 cross = (b - a).cross(c - a);
    const double length = cross.norm();
    faceNormals_[t] = length > 0.0 ? Vec3(cross / length) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      const int i = T[t][k], j = T[t][(k + 1) % 3], l = T[t][(k + 2) % 3];
      vertexNormals_[i] += cornerAngle(V[i], V[j], V[l]) * faceNormals_[t];
      edgeSums[edgeOf_[3 * t + k]] += faceNormals_[t];
    }
  }
  edgeNormals_.resize(3 * T.size());
  for (size_t e = 0; e < edgeOf_.size(); ++e) edgeNormals_[e] = edgeSums[edgeOf_[e]];
}

bool MeshCollider::onOpenEdge(const ClosestPoint& closest) const {
  if (openEdge_.empty()) return false;
  const Triangle& tri = surface_.triangles[closest.triangle];
  switch (closest.feature) {
    case TriangleFeature::Face:
      return false;
    case TriangleFeature::Edge01:
      return openEdge_[3 * closest.triangle + 0];
    case TriangleFeature::Edge12:
      return openEdge_[3 * closest.triangle + 1];
    case TriangleFeature::Edge20:
      return openEdge_[3 * closest.triangle + 2];
    case TriangleFeature::Vertex0:
      return openVertex_[tri[0]];
    case TriangleFeature::Vertex1:
      return openVertex_[tri[1]];
    case TriangleFeature::Vertex2:
      return openVertex_[tri[2]];
  }
  return false;
}

bool MeshCollider::contact(const Vec3& p, double clearance, double searchRadius, Contact& out) const {
  const ClosestPoint closest = bvh_.closest(p, searchRadius);
  if (closest.triangle < 0) {
    out.distance = searchRadius;
    return false;
  }
  const Triangle& tri = surface_.triangles[closest.triangle];
  Vec3 pseudoNormal = faceNormals_[closest.triangle];
  switch (closest.feature) {
    case TriangleFeature::Face:
      pseudoNormal = faceNormals_[closest.triangle];
      break;
    case TriangleFeature::Edge01:
      pseudoNormal = edgeNormals_[3 * closest.triangle + 0];
      break;
    case TriangleFeature::Edge12:
      pseudoNormal = edgeNormals_[3 * closest.triangle + 1];
      break;
    case TriangleFeature::Edge20:
      pseudoNormal = edgeNormals_[3 * closest.triangle + 2];
      break;
    case TriangleFeature::Vertex0:
      pseudoNormal = vertexNormals_[tri[0]];
      break;
    case TriangleFeature::Vertex1:
      pseudoNormal = vertexNormals_[tri[1]];
      break;
    case TriangleFeature::Vertex2:
      pseudoNormal = vertexNormals_[tri[2]];
      break;
  }
  const Vec3 offset = p - closest.point;
  const double distance = std::sqrt(closest.distanceSquared);
  const bool inside = offset.dot(pseudoNormal) < 0.0 && !onOpenEdge(closest);
  out.surfacePoint = closest.point;
  out.distance = inside ? -distance : distance;
  // Push-out direction: along the true offset when it is well defined, else the
  // pseudo-normal (a point on the surface itself).
  if (distance > 1e-9)
    out.normal = inside ? Vec3(-offset / distance) : Vec3(offset / distance);
  else
    out.normal = pseudoNormal.normalized();
  return out.distance < clearance;
}

}  // namespace figment

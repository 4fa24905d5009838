#include "sim/progressive/CollapseEnergy.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace figment {

namespace {
Eigen::Matrix4d planeQuadric(const Vec3& normal, const Vec3& point, double weight) {
  const Eigen::Vector4d plane(normal.x(), normal.y(), normal.z(), -normal.dot(point));
  return weight * plane * plane.transpose();
}

double quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double squares = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  const double area = 0.5 * (b - a).cross(c - a).norm();
  return squares > 0.0 ? 4.0 * std::sqrt(3.0) * area / squares : 0.0;
}
}  // namespace

CollapseEnergy::CollapseEnergy(const TriangleMesh& garment, const DecimationOptions& options)
    : options_(options), quadric_(garment.vertices.size(), Eigen::Matrix4d::Zero()) {
  const CollapseNeighbourhood mesh(garment);
  for (const Triangle& t : garment.triangles) {
    const Vec3 &a = garment.vertices[t[0]], &b = garment.vertices[t[1]], &c = garment.vertices[t[2]];
    const Vec3 cross = (b - a).cross(c - a);
    const double area = 0.5 * cross.norm();
    originalNormal_.push_back(area > 0.0 ? Vec3(cross.normalized()) : Vec3::Zero());
    const Eigen::Matrix4d surface = planeQuadric(originalNormal_.back(), a, area);
    for (int v : t) quadric_[v] += surface;
    for (int e = 0; e < 3; ++e) {
      const int from = t[e], to = t[(e + 1) % 3];
      if (!mesh.boundaryEdge(from, to)) continue;
      const Vec3 edge = garment.vertices[to] - garment.vertices[from];
      const Vec3 across = edge.cross(originalNormal_.back());
      if (across.norm() == 0.0) continue;
      const Eigen::Matrix4d perimeter =
          planeQuadric(across.normalized(), garment.vertices[from], options.perimeterWeight * edge.squaredNorm());
      quadric_[from] += perimeter, quadric_[to] += perimeter;
    }
  }
}

std::optional<double> CollapseEnergy::cost(const CollapseNeighbourhood& mesh, int kept, int removed,
                                           const Vec3& p) const {
  const double minTurnCosine = std::cos(options_.maxTurnDegrees * std::numbers::pi / 180.0);
  double squaredAreas = 0.0;
  for (int v : {kept, removed})
    for (int f : mesh.faces(v)) {
      Triangle t = mesh.corners(f);
      if (std::count(t.begin(), t.end(), kept) + std::count(t.begin(), t.end(), removed) == 2) continue;  // goes
      std::array<Vec3, 3> x;
      for (int c = 0; c < 3; ++c) x[c] = t[c] == kept || t[c] == removed ? p : mesh.rest(t[c]);
      const Vec3 cross = (x[1] - x[0]).cross(x[2] - x[0]);
      const double length = cross.norm();
      if (length == 0.0 || cross.dot(originalNormal_[f]) < minTurnCosine * length) return std::nullopt;
      if (quality(x[0], x[1], x[2]) < options_.minQuality) return std::nullopt;
      squaredAreas += 0.25 * length * length;
    }
  const Eigen::Vector4d h(p.x(), p.y(), p.z(), 1.0);
  const double distance = h.dot((quadric_[kept] + quadric_[removed]) * h);
  return std::max(0.0, distance) + options_.homogeneity * squaredAreas;
}

std::optional<Collapse> CollapseEnergy::best(const CollapseNeighbourhood& mesh, int a, int b) const {
  // The link condition: the vertices both see are exactly the edge's faces' third corners.
  const std::vector<int> edgeFaces = mesh.edgeFaces(a, b);
  if (edgeFaces.empty()) return std::nullopt;
  const std::vector<int> ringA = mesh.ring(a), ringB = mesh.ring(b);
  int shared = 0;
  for (int v : ringA) shared += std::count(ringB.begin(), ringB.end(), v);
  if (shared != static_cast<int>(edgeFaces.size())) return std::nullopt;
  const bool edgeOnBoundary = edgeFaces.size() == 1;
  const bool aOnBoundary = mesh.boundaryVertex(a), bOnBoundary = mesh.boundaryVertex(b);
  if (aOnBoundary && bOnBoundary && !edgeOnBoundary) return std::nullopt;  // would join two boundaries
  // Candidates: into a, into b, into the midpoint (kept a); a boundary vertex stays put
  // unless the edge runs along the boundary.
  std::vector<Collapse> candidates;
  if (!bOnBoundary || edgeOnBoundary) candidates.push_back({a, b, mesh.rest(a)});
  if (!aOnBoundary || edgeOnBoundary) candidates.push_back({b, a, mesh.rest(b)});
  if (aOnBoundary == bOnBoundary) candidates.push_back({a, b, 0.5 * (mesh.rest(a) + mesh.rest(b))});
  std::optional<Collapse> out;
  for (Collapse& candidate : candidates) {
    const std::optional<double> c = cost(mesh, candidate.kept, candidate.removed, candidate.position);
    if (!c) continue;
    candidate.cost = *c;
    if (!out || candidate.cost < out->cost) out = candidate;
  }
  return out;
}

}  // namespace figment

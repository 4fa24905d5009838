#include "BodyParts.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace figment {

std::vector<PartMesh> splitIntoParts(const TriangleMesh& body, const Skeleton& skeleton) {
  std::vector<Vec3> centroids;
  for (const Triangle& t : body.triangles)
    centroids.push_back((body.vertices[t[0]] + body.vertices[t[1]] + body.vertices[t[2]]) / 3.0);
  const std::vector<int> owner = assignParts(skeleton, centroids);
  std::vector<PartMesh> parts;
  for (const BodyPart& p : skeleton.parts)
    parts.push_back({p.name, {}, skeleton.joints[p.from].position, skeleton.joints[p.to].position});
  std::vector<std::vector<int>> local(parts.size(), std::vector<int>(body.vertices.size(), -1));
  for (size_t t = 0; t < body.triangles.size(); ++t) {
    PartMesh& part = parts[owner[t]];
    std::vector<int>& map = local[owner[t]];
    Triangle kept;
    for (int k = 0; k < 3; ++k) {
      const int v = body.triangles[t][k];
      if (map[v] < 0) map[v] = static_cast<int>(part.mesh.vertices.size()), part.mesh.vertices.push_back(body.vertices[v]);
      kept[k] = map[v];
    }
    part.mesh.triangles.push_back(kept);
  }
  return parts;
}

RadialDepthVolume fitRadialPart(const PartMesh& part, int harmonics, double sectionSpacing) {
  const Vec3 direction = (part.to - part.from).normalized();
  double low = std::numeric_limits<double>::max(), high = -low, farthest = 0.0;
  for (const Vec3& v : part.mesh.vertices) {
    const double s = (v - part.from).dot(direction);
    low = std::min(low, s), high = std::max(high, s);
    farthest = std::max(farthest, (v - part.from - s * direction).norm());
  }
  // A hair beyond the extreme vertices, so the caps enclose them.
  const double margin = 1e-4;
  const double length = high - low + 2 * margin;
  const int sections = std::max(2, static_cast<int>(std::ceil(length / sectionSpacing)) + 1);
  return fitRadialDepth(part.mesh, part.from + (low - margin) * direction, direction, length, farthest + 1.0, sections,
                        harmonics);
}

}  // namespace figment

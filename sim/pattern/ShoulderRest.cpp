#include "sim/pattern/ShoulderRest.h"

#include <algorithm>
#include <vector>

#include "sim/pattern/EdgeCurves.h"

namespace figment {

namespace {

// The edge's sample points, placed in the body's frame.
std::vector<Vec3> placedSamples(const Panel& panel, int edge, int segments) {
  std::vector<Vec3> points;
  for (const Vec2& p : sampleEdge(panel, edge, segments))
    points.push_back(panel.rotation * Vec3(p.x(), p.y(), 0.0) + panel.translation);
  return points;
}

}  // namespace

bool inside(const TriangleMesh& body, const Vec3& p) {
  // A closed surface: a point inside it lies under an odd number of its crossings.
  return crossingsAbove(body, p.x(), p.z(), p.y()).size() % 2 == 1;
}

std::vector<Crossing> crossingsAbove(const TriangleMesh& body, double x, double z, double from) {
  std::vector<Crossing> crossings;
  for (const Triangle& t : body.triangles) {
    const Vec3 &a = body.vertices[t[0]], &b = body.vertices[t[1]], &c = body.vertices[t[2]];
    // Barycentric coordinates of (x, z) in the triangle's shadow on the xz plane; a
    // triangle seen edge-on from above (a vertical wall) is not crossed.
    const double d = (b.x() - a.x()) * (c.z() - a.z()) - (c.x() - a.x()) * (b.z() - a.z());
    if (d == 0.0) continue;
    const double u = ((x - a.x()) * (c.z() - a.z()) - (c.x() - a.x()) * (z - a.z())) / d;
    const double v = ((b.x() - a.x()) * (z - a.z()) - (x - a.x()) * (b.z() - a.z())) / d;
    // Half-open on two edges, so a line through a shared edge counts it once.
    if (u < 0.0 || v < 0.0 || u + v >= 1.0) continue;
    const double y = a.y() + u * (b.y() - a.y()) + v * (c.y() - a.y());
    if (y > from) crossings.push_back({y, (b - a).cross(c - a).normalized().y()});
  }
  std::sort(crossings.begin(), crossings.end(), [](const Crossing& p, const Crossing& q) { return p.y < q.y; });
  return crossings;
}

double shoulderRise(const SewingPattern& pattern, const TriangleMesh& body, const ShoulderRestOptions& options) {
  double rise = 0.0;
  const int n = options.samples;
  for (const Stitch& stitch : pattern.stitches) {
    if (stitch.first.panel == stitch.second.panel) continue;  // a dart
    const std::vector<Vec3> a = placedSamples(pattern.panels[stitch.first.panel], stitch.first.edge, n);
    const std::vector<Vec3> b = placedSamples(pattern.panels[stitch.second.panel], stitch.second.edge, n);
    for (int k = 0; k <= n; ++k) {
      // Paired by fraction of arc length as the cutting pairs them (PatternCutting.h).
      const Vec3 &p = a[k], &q = b[stitch.sameDirection ? k : n - k], middle = 0.5 * (p + q);
      const std::vector<Crossing> above = crossingsAbove(body, middle.x(), middle.z(), middle.y());
      if (above.size() != 1 || above[0].y - middle.y() > options.reach || above[0].up < options.upward) continue;
      if (inside(body, p) || inside(body, q)) continue;
      rise = std::max(rise, above[0].y - middle.y() + options.clearance);
    }
  }
  return rise;
}

}  // namespace figment

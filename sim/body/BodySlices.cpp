// Body cross sections. Based on:
// - plane/triangle sections by edge crossings: a crossed edge (p, q) with signed heights
//   d_p, d_q of opposite sign meets the plane at p + d_p / (d_p - d_q) (q - p);
// - convex hulls by Andrew's monotone chain (Andrew 1979; de Berg et al., Computational
//   Geometry, §1.1);
// - polygon area centroid: C = 1/(6A) sum (p_i + p_{i+1}) cross(p_i, p_{i+1});
// - the offset of a convex set by a distance c (its Minkowski sum with a disc): along a ray
//   leaving the set the distance to it never decreases, so its boundary is found by bisection;
//   that boundary is made of the edges moved out by c and arcs of radius c round the corners,
//   so a ray's exit is also the furthest of its crossings with those (offsetExit).

#include "sim/body/BodySlices.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace figment {

namespace {

constexpr double kScanStep = 0.005;        // m between heights when scanning the body
constexpr double kArmpitTolerance = 1e-3;  // m
constexpr double kHeadWidening = 0.015;    // m of width above the narrowest section: the head
// m^2: turns this close to straight are dropped from hulls (points on a hull's side, such as
// where a plane crosses a flat face's diagonal, are not corners)
constexpr double kCollinear = 1e-15;

double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Vec2 inPlane(const Vec3& p, SectionAxis axis) {
  switch (axis) {
    case SectionAxis::X:
      return {p.z(), p.y()};
    case SectionAxis::Y:
      return {p.x(), p.z()};
    case SectionAxis::Z:
      return {p.x(), p.y()};
  }
  return {p.x(), p.z()};
}

int axisIndex(SectionAxis axis) {
  return axis == SectionAxis::X ? 0 : axis == SectionAxis::Y ? 1 : 2;
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double s = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + s * ab - p).norm();
}

// Where the ray origin + t direction (origin inside the convex `hull`, direction a unit
// vector) leaves the hull's offset by `clearance`: the largest t at which the ray is within
// the clearance of an edge's strip (the edge moved out along its normal) or of a corner
// (a circle round it). Every such point lies in the offset set and the exit is one of them,
// so the largest is the exit.
double offsetExit(const std::vector<Vec2>& hull, const Vec2& origin, const Vec2& direction, double clearance) {
  double exit = 0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2 edge = hull[(i + 1) % hull.size()] - a;
    const double length = edge.norm();
    if (length > 0) {
      // counter-clockwise: the outside lies to the edge's right
      const Vec2 outward = Vec2(edge.y(), -edge.x()) / length;
      const double towards = outward.dot(direction);
      if (towards > 0) {
        const double t = (clearance - outward.dot(origin - a)) / towards;
        const double s = (origin + t * direction - a).dot(edge) / (length * length);
        if (s >= 0 && s <= 1) exit = std::max(exit, t);
      }
    }
    const Vec2 fromCorner = origin - a;
    const double b = direction.dot(fromCorner), c = fromCorner.squaredNorm() - clearance * clearance;
    if (b * b - c >= 0) exit = std::max(exit, -b + std::sqrt(b * b - c));
  }
  return exit;
}

// The torso-band clusters' x-extent at a height and whether a cluster lies apart on each side.
struct TorsoExtent {
  bool found = false;
  double minX = 0, maxX = 0;
  bool apartOnBothSides = false;
  double width() const { return found ? maxX - minX : 0.0; }
};

bool reachesTorsoBand(const XCluster& c, const SliceOptions& options) {
  return c.maxX >= options.torsoCentreX - options.torsoHalfWidth &&
         c.minX <= options.torsoCentreX + options.torsoHalfWidth;
}

TorsoExtent torsoExtent(const TriangleMesh& body, double height, const SliceOptions& options) {
  const std::vector<XCluster> clusters = clusterByX(planeSection(body, SectionAxis::Y, height), options.clusterGap);
  TorsoExtent extent;
  for (const XCluster& c : clusters) {
    if (!reachesTorsoBand(c, options)) continue;
    extent.minX = extent.found ? std::min(extent.minX, c.minX) : c.minX;
    extent.maxX = extent.found ? std::max(extent.maxX, c.maxX) : c.maxX;
    extent.found = true;
  }
  if (!extent.found) return extent;
  bool left = false, right = false;
  for (const XCluster& c : clusters) {
    left = left || c.maxX < extent.minX;
    right = right || c.minX > extent.maxX;
  }
  extent.apartOnBothSides = left && right;
  return extent;
}

}  // namespace

std::vector<Vec2> convexHull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= kCollinear) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= kCollinear) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

std::vector<Segment2> planeSection(const TriangleMesh& mesh, SectionAxis axis, double value) {
  const int k = axisIndex(axis);
  std::vector<Segment2> segments;
  for (const Triangle& t : mesh.triangles) {
    const Vec3* p[3] = {&mesh.vertices[t[0]], &mesh.vertices[t[1]], &mesh.vertices[t[2]]};
    double d[3];
    for (int i = 0; i < 3; ++i) d[i] = (*p[i])[k] - value;
    // A vertex exactly on the plane counts as above it, so every crossing is seen once.
    Vec2 ends[2];
    int found = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if ((d[i] >= 0) == (d[j] >= 0)) continue;
      const double s = d[i] / (d[i] - d[j]);
      if (found < 2) ends[found] = inPlane(*p[i] + s * (*p[j] - *p[i]), axis);
      ++found;
    }
    if (found == 2) segments.push_back({ends[0], ends[1]});
  }
  return segments;
}

std::vector<XCluster> clusterByX(std::vector<Segment2> segments, double gap) {
  auto minX = [](const Segment2& s) { return std::min(s.a.x(), s.b.x()); };
  auto maxX = [](const Segment2& s) { return std::max(s.a.x(), s.b.x()); };
  std::sort(segments.begin(), segments.end(), [&](const Segment2& a, const Segment2& b) {
    return minX(a) < minX(b) || (minX(a) == minX(b) && maxX(a) < maxX(b));
  });
  std::vector<XCluster> clusters;
  for (const Segment2& s : segments) {
    if (clusters.empty() || minX(s) - clusters.back().maxX > gap) clusters.push_back({minX(s), maxX(s), {}});
    clusters.back().maxX = std::max(clusters.back().maxX, maxX(s));
    clusters.back().points.push_back(s.a);
    clusters.back().points.push_back(s.b);
  }
  return clusters;
}

Vec2 TorsoSlice::centroid() const {
  assert(!empty());
  double area2 = 0;
  Vec2 sum = Vec2::Zero();
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2& b = hull[(i + 1) % hull.size()];
    const double w = cross(a, b);
    area2 += w;
    sum += w * (a + b);
  }
  return sum / (3.0 * area2);
}

bool TorsoSlice::contains(const Vec2& p) const {
  if (empty()) return false;
  for (size_t i = 0; i < hull.size(); ++i)
    if (cross(hull[(i + 1) % hull.size()] - hull[i], p - hull[i]) < 0) return false;
  return true;
}

double TorsoSlice::minX() const {
  double m = std::numeric_limits<double>::infinity();
  for (const Vec2& p : hull) m = std::min(m, p.x());
  return m;
}

double TorsoSlice::maxX() const {
  double m = -std::numeric_limits<double>::infinity();
  for (const Vec2& p : hull) m = std::max(m, p.x());
  return m;
}

double TorsoSlice::reach(const Vec2& origin, const Vec2& direction, double clearance) const {
  assert(contains(origin) && clearance >= 0);
  double exit = 0;
  for (size_t i = 0; i < hull.size(); ++i) {
    const Vec2& a = hull[i];
    const Vec2 edge = hull[(i + 1) % hull.size()] - a;
    const double denominator = cross(direction, edge);
    if (std::abs(denominator) < 1e-15) continue;
    const double t = cross(a - origin, edge) / denominator;
    const double s = cross(a - origin, direction) / denominator;
    if (s >= -1e-12 && s <= 1 + 1e-12) exit = std::max(exit, t);
  }
  if (clearance == 0) return exit;

  auto distance = [&](double t) {
    const Vec2 q = origin + t * direction;
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < hull.size(); ++i)
      best = std::min(best, distanceToSegment(q, hull[i], hull[(i + 1) % hull.size()]));
    return best;
  };
  // The bisection below decides "still within the clearance" by the offset boundary found
  // directly (offsetExit): each distance() walks the whole hull, and a ring of a garment
  // asks a hundred sections at every angle, which made cutting a pencil skirt a fifth of a
  // size recommendation. Within kNearBoundary of that boundary the distance is measured as
  // before, so the bisection takes the same steps and returns the same bits as it did.
  constexpr double kNearBoundary = 1e-11;  // m: far above the rounding of either, far below its 1e-9
  const double boundary = offsetExit(hull, origin, direction, clearance);
  auto within = [&](double t) {
    return std::abs(t - boundary) > kNearBoundary ? t < boundary : distance(t) < clearance;
  };
  double low = exit, high = exit + clearance;
  while (within(high)) high += clearance;
  while (high - low > 1e-9) {
    const double mid = 0.5 * (low + high);
    (within(mid) ? low : high) = mid;
  }
  return high;
}

TorsoSlice sliceTorso(const TriangleMesh& body, double height, const SliceOptions& options) {
  std::vector<Vec2> torsoPoints;
  for (const XCluster& c : clusterByX(planeSection(body, SectionAxis::Y, height), options.clusterGap))
    if (reachesTorsoBand(c, options)) torsoPoints.insert(torsoPoints.end(), c.points.begin(), c.points.end());
  return {height, convexHull(std::move(torsoPoints))};
}

double armpitHeight(const TriangleMesh& body, const SliceOptions& options) {
  const Bounds bounds = boundsOf(body.vertices);
  const double bottom = bounds.min.y() + 0.5 * bounds.size().y();
  const double top = bounds.min.y() + 0.9 * bounds.size().y();

  double widestHeight = bottom, widest = -1;
  for (double y = bottom; y <= top; y += kScanStep) {
    const double width = torsoExtent(body, y, options).width();
    if (width > widest) widest = width, widestHeight = y;
  }
  if (torsoExtent(body, widestHeight, options).apartOnBothSides)
    throw std::invalid_argument("body: the arms never join the torso between 50% and 90% of its height");

  for (double merged = widestHeight, y = widestHeight - kScanStep; y >= bottom; merged = y, y -= kScanStep) {
    if (!torsoExtent(body, y, options).apartOnBothSides) continue;
    double apart = y;
    while (merged - apart > kArmpitTolerance) {
      const double mid = 0.5 * (apart + merged);
      (torsoExtent(body, mid, options).apartOnBothSides ? apart : merged) = mid;
    }
    return apart;
  }
  throw std::invalid_argument("body: the arms never part from the torso below its widest section");
}

double neckHeight(const TriangleMesh& body, double armpit, const SliceOptions& options) {
  const double top = boundsOf(body.vertices).max.y();
  // Start where the arms have joined: just below, the torso alone is narrower than the
  // shoulders, and the widening from it to them is not the head.
  double start = armpit;
  while (start < top && torsoExtent(body, start, options).apartOnBothSides) start += kArmpitTolerance;
  double narrowest = std::numeric_limits<double>::infinity(), neck = top;
  for (double y = start; y < top; y += kScanStep) {
    const TorsoExtent extent = torsoExtent(body, y, options);
    if (!extent.found) continue;  // a plane exactly through flat faces sees nothing
    if (extent.width() < narrowest) narrowest = extent.width(), neck = y;
    if (extent.width() > narrowest + kHeadWidening) break;
  }
  return neck;
}

SliceOptions centredSlicing(const TriangleMesh& body, double clusterGap, double torsoHalfWidth) {
  const Bounds bounds = boundsOf(body.vertices);
  SliceOptions slicing;
  slicing.clusterGap = clusterGap;
  slicing.torsoHalfWidth = torsoHalfWidth;
  slicing.torsoCentreX = 0.5 * (bounds.min.x() + bounds.max.x());
  return slicing;
}

}  // namespace figment

#include "sim/body/BaseLayer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace figment {

namespace {

constexpr int kTrunk = 0, kLeftThigh = 8, kRightThigh = 9;  // sim/body/SkinParts.h's order

// A point of a clipped skin triangle: its weights over the triangle's three corners.
using CornerWeights = std::array<double, 3>;

// A half-space a*x + b*y + c >= 0 of rest positions.
struct HalfSpace {
  double a = 0, b = 0, c = 0;
  double at(const Vec3& p) const { return a * p.x() + b * p.y() + c; }
};

// Sutherland-Hodgman against one half-space; `corner` are the triangle's rest corners.
std::vector<CornerWeights> clip(const std::vector<CornerWeights>& polygon, const HalfSpace& h,
                                const std::array<Vec3, 3>& corner) {
  auto value = [&](const CornerWeights& w) { return h.at(w[0] * corner[0] + w[1] * corner[1] + w[2] * corner[2]); };
  std::vector<CornerWeights> out;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const CornerWeights& p = polygon[k];
    const CornerWeights& q = polygon[(k + 1) % polygon.size()];
    const double fp = value(p), fq = value(q);
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) {
      const double t = fp / (fp - fq);
      out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), p[2] + t * (q[2] - p[2])});
    }
  }
  return out;
}

// Gives each clipped point one index: a skin vertex, or a point on a skin edge, is the
// same for the two triangles that share it.
class WeldedPoints {
 public:
  WeldedPoints(const std::vector<Vec3>& posed, const std::vector<Vec3>& normals, double offset)
      : posed_(posed), normals_(normals), offset_(offset) {}

  int index(const Triangle& t, const CornerWeights& w) {
    constexpr double kOnCorner = 1e-12;
    std::array<int, 3> used{};
    int count = 0;
    for (int k = 0; k < 3; ++k)
      if (w[size_t(k)] > kOnCorner) used[size_t(count++)] = k;
    Key key{-1, -1, 0};
    if (count == 1) key = {t[size_t(used[0])], -1, 0};
    if (count == 2) {
      int a = used[0], b = used[1];
      if (t[size_t(a)] > t[size_t(b)]) std::swap(a, b);
      key = {t[size_t(a)], t[size_t(b)], std::llround(w[size_t(a)] * double(1 << 30))};
    }
    if (count == 3) key = {-2 - int(mesh.vertices.size()), -1, 0};  // inside one triangle: its own
    const auto found = points_.find(key);
    if (found != points_.end()) return found->second;
    Vec3 position = Vec3::Zero(), normal = Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      position += w[size_t(k)] * posed_[size_t(t[size_t(k)])];
      normal += w[size_t(k)] * normals_[size_t(t[size_t(k)])];
    }
    if (normal.norm() > 0) position += offset_ * normal.normalized();
    mesh.vertices.push_back(position);
    return points_[key] = int(mesh.vertices.size()) - 1;
  }

  TriangleMesh mesh;

 private:
  using Key = std::tuple<int, int, long long>;
  const std::vector<Vec3>& posed_;
  const std::vector<Vec3>& normals_;
  double offset_;
  std::map<Key, int> points_;
};

// One piece: the triangles of `parts` clipped to `bounds`, fanned into `out`.
void cutPiece(const TriangleMesh& rest, const std::vector<int>& triangleParts, std::initializer_list<int> parts,
              const std::vector<HalfSpace>& bounds, WeldedPoints& out) {
  for (size_t i = 0; i < rest.triangles.size(); ++i) {
    if (std::find(parts.begin(), parts.end(), triangleParts[i]) == parts.end()) continue;
    const Triangle& t = rest.triangles[i];
    const std::array<Vec3, 3> corner = {rest.vertices[size_t(t[0])], rest.vertices[size_t(t[1])],
                                        rest.vertices[size_t(t[2])]};
    std::vector<CornerWeights> polygon = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const HalfSpace& h : bounds) {
      polygon = clip(polygon, h, corner);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;
    std::vector<int> index;
    for (const CornerWeights& w : polygon) index.push_back(out.index(t, w));
    for (size_t k = 1; k + 1 < index.size(); ++k) {
      const Triangle fan = {index[0], index[k], index[k + 1]};
      if (fan[0] != fan[1] && fan[1] != fan[2] && fan[0] != fan[2]) out.mesh.triangles.push_back(fan);
    }
  }
}

}  // namespace

BaseLayerBounds baseLayerBounds(const TriangleMesh& rest, const std::vector<int>& triangleParts,
                                const BodyLandmarks& landmarks, const BaseLayerShape& shape) {
  const BodyLandmarks& l = landmarks;
  if (!(l.crotch < l.hip && l.hip < l.waist && (!shape.top || (l.underbust < l.bust && l.bust < l.armpit))))
    throw std::invalid_argument("base layer: the body's landmarks are out of order (crotch " +
                                std::to_string(l.crotch) + ", hip " + std::to_string(l.hip) + ", waist " +
                                std::to_string(l.waist) + " m)");
  BaseLayerBounds b;
  const Bounds box = boundsOf(rest.vertices);
  b.centreX = 0.5 * (box.min.x() + box.max.x());
  double halfWidth = 0;  // the trunk's, 1 cm about hip level
  for (size_t i = 0; i < rest.triangles.size() && i < triangleParts.size(); ++i)
    if (triangleParts[i] == kTrunk)
      for (int v : rest.triangles[i])
        if (std::abs(rest.vertices[size_t(v)].y() - l.hip) < 0.01)
          halfWidth = std::max(halfWidth, std::abs(rest.vertices[size_t(v)].x() - b.centreX));
  if (halfWidth <= 0) throw std::invalid_argument("base layer: no trunk at hip level");
  b.briefsTop = l.hip + (l.waist - l.hip) / 3;
  b.legBottom = l.crotch - 0.015;
  b.legSlope = (l.hip - b.legBottom) / halfWidth;
  if (shape.top) {
    b.bandBottom = l.underbust - 0.02;
    b.bandTop = l.bust + 0.5 * (l.armpit - l.bust);
  }
  return b;
}

TriangleMesh cutBaseLayer(const TriangleMesh& rest, const TriangleMesh& posed, const std::vector<int>& triangleParts,
                          const BaseLayerBounds& bounds, const BaseLayerShape& shape) {
  if (rest.vertices.size() != posed.vertices.size() || rest.triangles.size() != posed.triangles.size() ||
      triangleParts.size() != rest.triangles.size())
    throw std::invalid_argument("base layer: the rest body (" + std::to_string(rest.triangles.size()) +
                                " triangles), the posed body (" + std::to_string(posed.triangles.size()) +
                                ") and the parts (" + std::to_string(triangleParts.size()) + ") disagree");
  const std::vector<Vec3> normals = vertexNormals(posed);
  WeldedPoints out(posed.vertices, normals, shape.offset);
  const BaseLayerBounds& b = bounds;
  // y <= top; y >= legBottom + slope |x - centre|, as two half-spaces, one per leg.
  const std::vector<HalfSpace> briefs = {{0, -1, b.briefsTop},
                                         {-b.legSlope, 1, -b.legBottom + b.legSlope * b.centreX},
                                         {b.legSlope, 1, -b.legBottom - b.legSlope * b.centreX}};
  cutPiece(rest, triangleParts, {kTrunk, kLeftThigh, kRightThigh}, briefs, out);
  if (b.bandTop > b.bandBottom)
    cutPiece(rest, triangleParts, {kTrunk}, {{0, 1, -b.bandBottom}, {0, -1, b.bandTop}}, out);
  return std::move(out.mesh);
}

}  // namespace figment

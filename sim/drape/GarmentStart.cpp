#include "sim/drape/GarmentStart.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace figment {

namespace {

// Metres per unit of the units a garment file is likely in: mm, cm, dm. An inch (0.0254)
// is too near a centimetre for a garment's size to tell them apart: the nearer power of
// ten is said.
constexpr std::array<double, 3> kUnits = {0.001, 0.01, 0.1};

// The unit that brings a garment of `ratio` times the body's size nearest (by ratio) to
// 0.6 of it, the shipped garments' size (the dress 0.55, the T-shirt 0.6).
double likelyUnit(double ratio) {
  double best = 1.0, bestMiss = std::numeric_limits<double>::infinity();
  for (double unit : kUnits) {
    const double miss = std::abs(std::log(ratio * unit / 0.6));
    if (miss < bestMiss) best = unit, bestMiss = miss;
  }
  return best;
}

// The proper rotation taking `d` (an axis direction) onto +y, as MeshFile's upAxis turns
// a file's axis up (io/UpAxis.h): 90 degrees about a horizontal axis, 180 about x for -y.
Eigen::Quaterniond upright(const Vec3& d) {
  if (d.y() < -0.5) return Eigen::Quaterniond(Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitX()));
  return Eigen::Quaterniond::FromTwoVectors(d, Vec3::UnitY());
}

// The axis direction that, turned up, makes `vertices` wear the body; none when they do
// already, or when no direction does.
std::optional<Vec3> upDirection(const std::vector<Vec3>& vertices, const Bounds& bodyBox) {
  if (wearsBody(vertices, bodyBox)) return std::nullopt;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {1.0, -1.0}) {
      const Vec3 d = sign * Vec3::Unit(axis);
      if (d.y() > 0.5) continue;
      const Eigen::Quaterniond turn = upright(d);
      std::vector<Vec3> turned;
      turned.reserve(vertices.size());
      for (const Vec3& v : vertices) turned.push_back(turn * v);
      if (wearsBody(turned, bodyBox)) return d;
    }
  return std::nullopt;
}

// Each node's share of the garment's area (a third of each triangle's) and its normal's
// direction (the area-weighted sum of its triangles' normals, counterclockwise = front).
void nodeAreas(const TriangleMesh& garment, std::vector<double>& area, std::vector<Vec3>& normal) {
  area.assign(garment.vertices.size(), 0.0);
  normal.assign(garment.vertices.size(), Vec3::Zero());
  for (const Triangle& t : garment.triangles) {
    const Vec3 n =
        (garment.vertices[t[1]] - garment.vertices[t[0]]).cross(garment.vertices[t[2]] - garment.vertices[t[0]]);
    for (int k = 0; k < 3; ++k) area[t[k]] += n.norm() / 6.0, normal[t[k]] += n;
  }
}

// Inside share and winding, from one contact query per node.
void measureAgainstSurface(const TriangleMesh& garment, const Collider& body, GarmentStart& start) {
  std::vector<double> area;
  std::vector<Vec3> normal;
  nodeAreas(garment, area, normal);
  double total = 0.0, near = 0.0, inward = 0.0;
  int inside = 0;
  for (size_t i = 0; i < garment.vertices.size(); ++i) {
    total += area[i];
    Contact contact{};
    // Searched 3 reaches deep, so that a node well inside (a waistband in the hips) is found.
    if (!body.contact(garment.vertices[i], GarmentStart::kWindingReach, 3 * GarmentStart::kWindingReach, contact))
      continue;
    if (contact.distance < 0.0) {
      ++inside;
      continue;
    }
    near += area[i];
    if (normal[i].dot(contact.normal) < 0.0) inward += area[i];
  }
  start.insideShare = garment.vertices.empty() ? 0.0 : double(inside) / double(garment.vertices.size());
  if (total > 0.0 && near >= GarmentStart::kWindingAreaShare * total) start.inwardShare = inward / near;
}

}  // namespace

bool wearsBody(const std::vector<Vec3>& vertices, const Bounds& bodyBox) {
  if (vertices.empty() || bodyBox.empty()) return false;
  const Bounds box = boundsOf(vertices);
  const Vec3 centre = 0.5 * (bodyBox.min + bodyBox.max);
  const bool round =
      box.min.x() <= centre.x() && centre.x() <= box.max.x() && box.min.z() <= centre.z() && centre.z() <= box.max.z();
  const double overlap = std::min(box.max.y(), bodyBox.max.y()) - std::max(box.min.y(), bodyBox.min.y());
  return round && overlap >= 0.5 * box.size().y();
}

GarmentStart checkGarmentStart(const TriangleMesh& garment, const std::optional<Bounds>& bodyBox,
                               const Collider* body) {
  GarmentStart start;
  if (garment.vertices.empty()) return start;
  start.extent = boundsOf(garment.vertices).size().maxCoeff();
  const bool haveBox = bodyBox && !bodyBox->empty();
  start.bodyExtent = haveBox ? bodyBox->size().maxCoeff() : GarmentStart::kTypicalStature;
  if (start.tooLarge()) start.unitFactor = likelyUnit(start.sizeRatio());
  if (!haveBox) return start;
  std::vector<Vec3> scaled = garment.vertices;
  for (Vec3& v : scaled) v *= start.unitFactor;
  start.up = upDirection(scaled, *bodyBox);
  if (!start.tooLarge() && !start.up && body) measureAgainstSurface(garment, *body, start);
  return start;
}

}  // namespace figment

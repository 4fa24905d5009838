#include "sim/garment/FlaredSkirt.h"

#include "sim/body/BodySlices.h"
#include "sim/core/ParameterChecks.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace figment {

namespace {

constexpr double kWaistSearchStep = 0.005;  // m between the sections compared for the waist
// The waist is looked for between these shares of the way from the body's bottom to the
// armpits: above the hips' widest part, below the ribs.
constexpr double kWaistSearchLow = 0.75, kWaistSearchHigh = 0.92;

double perimeter(const std::vector<Vec2>& polygon) {
  double length = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) length += (polygon[(i + 1) % polygon.size()] - polygon[i]).norm();
  return length;
}

// The narrowest torso section between the hips and the armpits.
TorsoSlice naturalWaist(const TriangleMesh& body, const SliceOptions& slicing) {
  const double bottom = boundsOf(body.vertices).min.y();
  const double armpit = armpitHeight(body, slicing);
  TorsoSlice waist;
  double narrowest = std::numeric_limits<double>::infinity();
  for (double y = bottom + kWaistSearchLow * (armpit - bottom); y <= bottom + kWaistSearchHigh * (armpit - bottom);
       y += kWaistSearchStep) {
    TorsoSlice slice = sliceTorso(body, y, slicing);
    if (slice.empty()) continue;
    if (const double p = perimeter(slice.hull); p < narrowest) narrowest = p, waist = std::move(slice);
  }
  if (waist.empty()) throw std::invalid_argument("body: no torso section between the hips and the armpits");
  return waist;
}

// Ring vertices first, then two triangles per quad, counter-clockwise seen from outside:
// around each ring the angle grows from +x towards +z, rings go down.
void addCone(const TorsoSlice& waist, const FlaredSkirtOptions& options, TriangleMesh& mesh) {
  const Vec2 centre = waist.centroid();
  for (int row = 0; row <= options.rows; ++row) {
    const double t = static_cast<double>(row) / options.rows;
    for (int column = 0; column < options.columns; ++column) {
      const double angle = 2.0 * M_PI * column / options.columns;
      const Vec2 direction(std::cos(angle), std::sin(angle));
      const double radius = waist.reach(centre, direction, options.waistClearance) + t * options.flare;
      const Vec2 p = centre + radius * direction;
      mesh.vertices.emplace_back(p.x(), waist.height - t * options.length, p.y());
    }
  }
  const int c = options.columns;
  for (int row = 0; row < options.rows; ++row)
    for (int column = 0; column < c; ++column) {
      const int a = row * c + column, b = row * c + (column + 1) % c;
      const int below = a + c, belowNext = b + c;
      mesh.triangles.push_back({a, b, below});
      mesh.triangles.push_back({b, belowNext, below});
    }
}

}  // namespace

void FlaredSkirtOptions::validate() const {
  requirePositive("waistClearance", waistClearance);
  requirePositive("length", length);
  requireNonNegative("flare", flare);
  if (rows < 1) throw std::invalid_argument("rows = " + std::to_string(rows) + " must be >= 1");
  if (columns < 8) throw std::invalid_argument("columns = " + std::to_string(columns) + " must be >= 8");
  requirePositive("clusterGap", clusterGap);
  requirePositive("torsoHalfWidth", torsoHalfWidth);
}

FlaredSkirt makeFlaredSkirt(const TriangleMesh& body, const FlaredSkirtOptions& options) {
  options.validate();
  if (body.triangles.empty()) throw std::invalid_argument("body: no triangles");
  const Bounds bounds = boundsOf(body.vertices);
  SliceOptions slicing;
  slicing.clusterGap = options.clusterGap;
  slicing.torsoHalfWidth = options.torsoHalfWidth;
  slicing.torsoCentreX = 0.5 * (bounds.min.x() + bounds.max.x());
  const TorsoSlice waist = naturalWaist(body, slicing);

  FlaredSkirt skirt;
  addCone(waist, options, skirt.mesh);
  skirt.waistHeight = waist.height;
  skirt.waistPerimeter = perimeter(waist.hull);
  skirt.hemHeight = waist.height - options.length;
  for (int column = 0; column < options.columns; ++column) {
    const Vec3 d = skirt.mesh.vertices[(column + 1) % options.columns] - skirt.mesh.vertices[column];
    skirt.waistbandPerimeter += d.norm();
  }
  for (const Triangle& t : skirt.mesh.triangles) {
    const Vec3& a = skirt.mesh.vertices[t[0]];
    skirt.area += 0.5 * (skirt.mesh.vertices[t[1]] - a).cross(skirt.mesh.vertices[t[2]] - a).norm();
  }
  return skirt;
}

}  // namespace figment

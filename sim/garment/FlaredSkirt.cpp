#include "sim/garment/FlaredSkirt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sim/body/BodySlices.h"
#include "sim/core/ParameterChecks.h"
#include "sim/garment/RingTube.h"

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
// around each ring the angle grows from +x towards +z, rings go down. A ring that would
// cut into the body (the seat bulges further out than the flare) is pushed out to the
// body's section there, plus the waist clearance.
void addCone(const TriangleMesh& body, const TorsoSlice& waist, const FlaredSkirtOptions& options,
             const SliceOptions& slicing, TriangleMesh& mesh) {
  const Vec2 centre = waist.centroid();
  for (int row = 0; row <= options.rows; ++row) {
    const double t = static_cast<double>(row) / options.rows;
    const double height = waist.height - t * options.length;
    const TorsoSlice section = row == 0 ? waist : sliceTorso(body, height, slicing);
    const bool around = !section.empty() && section.contains(centre);
    for (int column = 0; column < options.columns; ++column) {
      const double angle = 2.0 * M_PI * column / options.columns;
      const Vec2 direction(std::cos(angle), std::sin(angle));
      double radius = waist.reach(centre, direction, options.waistClearance) + t * options.flare;
      if (around) radius = std::max(radius, section.reach(centre, direction, options.waistClearance));
      const Vec2 p = centre + radius * direction;
      mesh.vertices.emplace_back(p.x(), height, p.y());
    }
  }
  addRingTubeTriangles(mesh, options.rows + 1, options.columns);
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
  const SliceOptions slicing = centredSlicing(body, options.clusterGap, options.torsoHalfWidth);
  const TorsoSlice waist = naturalWaist(body, slicing);

  FlaredSkirt skirt;
  addCone(body, waist, options, slicing, skirt.mesh);
  skirt.mesh = numberedByFirstUse(skirt.mesh);
  skirt.waistHeight = waist.height;
  skirt.waistPerimeter = perimeter(waist.hull);
  skirt.hemHeight = waist.height - options.length;
  for (const Triangle& t : skirt.mesh.triangles)  // the waistband: the edges along y = waist
    for (int k = 0; k < 3; ++k) {
      const Vec3 &a = skirt.mesh.vertices[t[k]], &b = skirt.mesh.vertices[t[(k + 1) % 3]];
      if (a.y() == waist.height && b.y() == waist.height) skirt.waistbandPerimeter += (b - a).norm();
    }
  skirt.area = surfaceArea(skirt.mesh);
  return skirt;
}

}  // namespace figment

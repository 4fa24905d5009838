// The pencil skirt generator. Method:
// 1. Landmarks from the body's tape measurements (sim/body/BodyMeasurements.h): the natural
//    waist and the hip level (where the seat reaches furthest back).
// 2. Rings from the waist down, each round one vertical axis (the waist section's centroid).
//    A ring's radius at an angle is the largest reach, at that angle, of the body's convex
//    torso sections from the waist down to the ring (sampled every 5 mm), offset by the
//    ring's ease: so the tube never narrows below the widest part above it (the straight
//    fall over the seat and the thighs) and never cuts into the body. The ease goes from
//    waistEase to hipEase between the waist and the hips as a radial offset of girth /
//    (2 pi), which is what offsetting a convex outline adds to its perimeter.
// 3. Below the hips the tube narrows linearly by `taper` of girth down to the hem, but never
//    to less than the ring's own body section plus the waist's ease (the thighs).
// 4. Windings: counter-clockwise seen from outside by construction (the angle grows from +x
//    towards +z, rings go down).

#include "sim/garment/PencilSkirt.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/body/BodyMeasurements.h"
#include "sim/body/BodySlices.h"
#include "sim/core/ParameterChecks.h"
#include "sim/garment/RingTube.h"

namespace figment {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kSectionStep = 0.005;  // m between the body sections a ring is kept clear of

// The radial offset (m) that adds `girth` (m) to a convex outline's perimeter.
double radialOffset(double girth) {
  return girth / kTwoPi;
}

// The body's convex torso sections from `top` down to `bottom`, every kSectionStep.
std::vector<TorsoSlice> sectionsBetween(const TriangleMesh& body, double top, double bottom,
                                        const SliceOptions& slicing) {
  std::vector<TorsoSlice> sections;
  for (double y = top; y >= bottom - 1e-9; y -= kSectionStep) {
    TorsoSlice slice = sliceTorso(body, y, slicing);
    if (!slice.empty()) sections.push_back(std::move(slice));
  }
  return sections;
}

// How far out (m) from `centre` along `direction` the ring at `height` lies.
double ringRadius(const std::vector<TorsoSlice>& sections, const PencilSkirt& skirt, const PencilSkirtOptions& options,
                  const Vec2& centre, const Vec2& direction, double height) {
  const double share = std::clamp((skirt.waistHeight - height) / (skirt.waistHeight - skirt.hipHeight), 0.0, 1.0);
  const double ease = radialOffset(options.waistEase + share * (options.hipEase - options.waistEase));
  double straight = 0.0, own = 0.0;
  for (const TorsoSlice& slice : sections) {
    if (slice.height < height - 1e-9 || !slice.contains(centre)) continue;
    const double reach = slice.reach(centre, direction, ease);
    straight = std::max(straight, reach);
    if (std::abs(slice.height - height) < 0.5 * kSectionStep) own = slice.reach(centre, direction, 0.0);
  }
  if (height >= skirt.hipHeight) return straight;
  const double below = (skirt.hipHeight - height) / (skirt.hipHeight - skirt.hemHeight);
  return std::max(straight - below * radialOffset(options.taper), own + radialOffset(options.waistEase));
}

void addTube(const std::vector<TorsoSlice>& sections, const PencilSkirtOptions& options, const Vec2& centre,
             PencilSkirt& skirt) {
  TriangleMesh& mesh = skirt.mesh;
  for (int row = 0; row <= options.rows; ++row) {
    const double height = skirt.waistHeight - options.length * row / options.rows;
    for (int column = 0; column < options.columns; ++column) {
      const double angle = kTwoPi * column / options.columns;
      const Vec2 direction(std::cos(angle), std::sin(angle));
      const Vec2 p = centre + ringRadius(sections, skirt, options, centre, direction, height) * direction;
      mesh.vertices.emplace_back(p.x(), height, p.y());
    }
  }
  addRingTubeTriangles(mesh, options.rows + 1, options.columns);
}

}  // namespace

void PencilSkirtOptions::validate() const {
  requireNonNegative("waistEase", waistEase);
  requireNonNegative("hipEase", hipEase);
  requirePositive("length", length);
  requireNonNegative("taper", taper);
  if (rows < 2) throw std::invalid_argument("rows = " + std::to_string(rows) + " must be >= 2");
  if (columns < 8) throw std::invalid_argument("columns = " + std::to_string(columns) + " must be >= 8");
  requirePositive("clusterGap", clusterGap);
  requirePositive("torsoHalfWidth", torsoHalfWidth);
}

PencilSkirt makePencilSkirt(const TriangleMesh& body, const PencilSkirtOptions& options) {
  options.validate();
  const BodyMeasurements measured = measureBody(body);
  PencilSkirt skirt;
  skirt.waistHeight = measured.landmarks.waist;
  skirt.hipHeight = measured.landmarks.hip;
  skirt.hemHeight = skirt.waistHeight - options.length;
  if (!(skirt.hipHeight > skirt.hemHeight && skirt.hipHeight < skirt.waistHeight))
    throw std::invalid_argument(
        "body: its hips do not lie between the waist and length = " + formatNumber(options.length) + " below it");
  const SliceOptions slicing = centredSlicing(body, options.clusterGap, options.torsoHalfWidth);
  const std::vector<TorsoSlice> sections = sectionsBetween(body, skirt.waistHeight, skirt.hemHeight, slicing);
  if (sections.empty() || sections.front().empty()) throw std::invalid_argument("body: no torso section at its waist");
  addTube(sections, options, sections.front().centroid(), skirt);
  return skirt;
}

}  // namespace figment

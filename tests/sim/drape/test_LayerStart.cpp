// A garment put on over a layer already draped starts clean over it: on two coaxial tubes,
// the outer one cut partly inside the inner, where every figure is known.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "sim/collision/MeshCollider.h"
#include "sim/drape/LayerStart.h"

using namespace figment;

namespace {

constexpr int kAround = 48, kRows = 41;
constexpr double kInner = 0.20, kClearance = 0.003;

// An open tube about the y axis from y = 0 to 1, radius by height, CCW seen from outside.
TriangleMesh tube(const std::function<double(double)>& radius) {
  TriangleMesh mesh;
  for (int r = 0; r < kRows; ++r)
    for (int s = 0; s < kAround; ++s) {
      const double y = double(r) / (kRows - 1), a = 2 * std::numbers::pi * s / kAround;
      mesh.vertices.emplace_back(radius(y) * std::sin(a), y, radius(y) * std::cos(a));
    }
  const auto at = [](int r, int s) { return r * kAround + s % kAround; };
  for (int r = 0; r + 1 < kRows; ++r)
    for (int s = 0; s < kAround; ++s) {
      mesh.triangles.push_back({at(r, s), at(r, s + 1), at(r + 1, s + 1)});
      mesh.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r + 1, s)});
    }
  return mesh;
}

// The outer garment: 1 cm inside the inner tube below y = 0.5, 5 cm outside above 0.6.
double outerRadius(double y) {
  return y < 0.5 ? kInner - 0.01 : y > 0.6 ? kInner + 0.05 : kInner - 0.01 + 0.6 * (y - 0.5);
}

double radial(const Vec3& p) {
  return std::hypot(p.x(), p.z());
}

}  // namespace

TEST(LayerStart, NodesUnderTheLayerStartOverItAtTheClearance) {
  const MeshCollider inner(tube([](double) { return kInner; }));
  const TriangleMesh outer = tube(outerRadius);
  const LayerStart start = startOverLayers(outer, inner, kClearance);
  ASSERT_EQ(start.positions.size(), outer.vertices.size());
  int under = 0;
  for (size_t i = 0; i < outer.vertices.size(); ++i) {
    const double y = outer.vertices[i].y();
    if (y > 0.02 && y < 0.98) EXPECT_GE(radial(start.positions[i]), kInner + kClearance - 2e-4) << i;
    under += radial(outer.vertices[i]) < kInner;
  }
  EXPECT_GE(start.moved, under);
  EXPECT_NEAR(start.largestMove, 0.01 + kClearance, 2e-3);
}

TEST(LayerStart, NodesFarOverTheLayerStayWhereTheyWereCut) {
  const MeshCollider inner(tube([](double) { return kInner; }));
  const TriangleMesh outer = tube(outerRadius);
  const LayerStart start = startOverLayers(outer, inner, kClearance);
  // The moves fade out within 8 rings (rows 2.5 cm apart) of the last row moved (y 0.5).
  for (size_t i = 0; i < outer.vertices.size(); ++i)
    if (outer.vertices[i].y() > 0.85) EXPECT_EQ(start.positions[i], outer.vertices[i]) << i;
}

TEST(LayerStart, TheMovesAreSpreadSoTheClothStartsSmooth) {
  // One ring pushed alone would start as a step between rows; spread, the rows above it
  // move too, each less than the one below.
  const MeshCollider inner(tube([](double) { return kInner; }));
  const TriangleMesh outer = tube(outerRadius);
  const LayerStart start = startOverLayers(outer, inner, kClearance);
  double below = 1.0;
  for (int row = 21; row < 31; ++row) {  // y 0.525 to 0.75, all cut outside the layer's reach
    const size_t i = size_t(row * kAround);
    const double moved = (start.positions[i] - outer.vertices[i]).norm();
    EXPECT_LE(moved, below + 1e-12) << "row " << row;
    below = moved;
  }
  EXPECT_GT((start.positions[size_t(21 * kAround)] - outer.vertices[size_t(21 * kAround)]).norm(), 1e-4);
}

TEST(LayerStart, AGarmentClearOfTheLayersStartsAsCut) {
  const MeshCollider inner(tube([](double) { return kInner; }));
  const TriangleMesh outer = tube([](double) { return kInner + 0.03; });
  const LayerStart start = startOverLayers(outer, inner, kClearance);
  EXPECT_EQ(start.moved, 0);
  EXPECT_EQ(start.largestMove, 0.0);
  EXPECT_EQ(start.positions, outer.vertices);
  EXPECT_THROW(startOverLayers(outer, inner, 0.0), std::invalid_argument);
}

#pragma once
// A tube of cloth round a closed cylinder (the body), as the fit tests measure it: cut at
// one radius, lying at another, the cylinder at a third (tests/sim/fit).

#include <cmath>
#include <vector>

#include "sim/fit/GarmentFit.h"

namespace figment::test {

constexpr int kColumns = 64, kRows = 10;
constexpr double kHeight = 0.4;  // m of the tube, from y = 0.8

// A tube of radius `radius` round the y axis from y = 0.8 up, wound outward.
inline TriangleMesh tube(double radius) {
  TriangleMesh mesh;
  for (int row = 0; row <= kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const double angle = 2.0 * M_PI * column / kColumns;
      mesh.vertices.emplace_back(radius * std::cos(angle), 0.8 + kHeight * row / kRows, radius * std::sin(angle));
    }
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const int a = row * kColumns + column, b = row * kColumns + (column + 1) % kColumns;
      // Rows go up here: (a, c, b) is counter-clockwise from outside.
      mesh.triangles.push_back({a, a + kColumns, b});
      mesh.triangles.push_back({b, a + kColumns, b + kColumns});
    }
  return mesh;
}

// A closed cylinder (the body) of radius `radius`, y from 0.5 to 1.5, with the tube's columns.
inline TriangleMesh cylinder(double radius) {
  TriangleMesh mesh;
  for (double y : {0.5, 1.5})
    for (int column = 0; column < kColumns; ++column) {
      const double angle = 2.0 * M_PI * column / kColumns;
      mesh.vertices.emplace_back(radius * std::cos(angle), y, radius * std::sin(angle));
    }
  const int bottom = static_cast<int>(mesh.vertices.size());
  mesh.vertices.emplace_back(0, 0.5, 0);
  mesh.vertices.emplace_back(0, 1.5, 0);
  for (int column = 0; column < kColumns; ++column) {
    const int a = column, b = (column + 1) % kColumns;
    mesh.triangles.push_back({a, a + kColumns, b});
    mesh.triangles.push_back({b, a + kColumns, b + kColumns});
    mesh.triangles.push_back({bottom, a, b});
    mesh.triangles.push_back({bottom + 1, b + kColumns, a + kColumns});
  }
  return mesh;
}

// One region round the tube's middle, its girth taken at y = 1.0 against the cylinder's section.
inline FitRegion middle(double bodyRadius) {
  FitRegion region;
  region.name = "waist";
  region.low = 0.85;
  region.high = 1.15;
  region.girthLevel = 1.0;
  for (int column = 0; column < kColumns; ++column) {
    const double angle = 2.0 * M_PI * column / kColumns;
    region.bodySection.hull.emplace_back(bodyRadius * std::cos(angle), bodyRadius * std::sin(angle));
  }
  region.bodySection.height = 1.0;
  return region;
}

struct Case {
  TriangleMesh rest;
  std::vector<Vec3> positions;
  MeshCollider body;
  FitInput input;
  Case(double restRadius, double drapedRadius, double bodyRadius, double clearance)
      : rest(tube(restRadius)), positions(tube(drapedRadius).vertices), body(cylinder(bodyRadius)) {
    input.rest = &rest;
    input.positions = &positions;
    input.body = &body;
    input.parameters.clearance = clearance;
    input.parameters.gravity = Vec3::Zero();
  }
};

}  // namespace figment::test

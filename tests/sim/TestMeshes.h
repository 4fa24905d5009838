#pragma once
// Small literal meshes for the sim tests, built in code so each test says what holds.

#include "sim/TriangleMesh.h"

#include <cmath>

namespace figment::meshes {

// A rectangular grid in the plane spanned by `right` and `down` from `origin`,
// nu x nv quads, each split along the same diagonal; vertex (i, j) = i + j (nu + 1).
inline TriangleMesh grid(int nu, int nv, double width, double height, const Vec3& origin = Vec3::Zero(),
                         const Vec3& right = Vec3::UnitX(), const Vec3& down = -Vec3::UnitY()) {
  TriangleMesh mesh;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i)
      mesh.vertices.push_back(origin + right * (width * i / nu) + down * (height * j / nv));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = i + j * (nu + 1), b = a + 1, c = a + nu + 1, d = c + 1;
      mesh.triangles.push_back({a, c, b});
      mesh.triangles.push_back({b, c, d});
    }
  return mesh;
}

// A closed UV sphere of radius r, counter-clockwise seen from outside.
inline TriangleMesh sphere(double r, int slices = 32, int stacks = 16, const Vec3& centre = Vec3::Zero()) {
  TriangleMesh mesh;
  mesh.vertices.push_back(centre + Vec3(0, r, 0));
  for (int s = 1; s < stacks; ++s) {
    const double polar = M_PI * s / stacks;
    for (int k = 0; k < slices; ++k) {
      const double azimuth = 2 * M_PI * k / slices;
      mesh.vertices.push_back(centre + r * Vec3(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                                -std::sin(polar) * std::sin(azimuth)));
    }
  }
  const int south = static_cast<int>(mesh.vertices.size());
  mesh.vertices.push_back(centre + Vec3(0, -r, 0));
  auto ring = [&](int s, int k) { return 1 + (s - 1) * slices + (k % slices); };
  for (int k = 0; k < slices; ++k) mesh.triangles.push_back({0, ring(1, k), ring(1, k + 1)});
  for (int s = 1; s < stacks - 1; ++s)
    for (int k = 0; k < slices; ++k) {
      mesh.triangles.push_back({ring(s, k), ring(s + 1, k), ring(s + 1, k + 1)});
      mesh.triangles.push_back({ring(s, k), ring(s + 1, k + 1), ring(s, k + 1)});
    }
  for (int k = 0; k < slices; ++k) mesh.triangles.push_back({south, ring(stacks - 1, k + 1), ring(stacks - 1, k)});
  return mesh;
}

}  // namespace figment::meshes

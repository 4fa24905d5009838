#pragma once
// Small literal meshes for the sim tests, built in code so each test says what holds.

#include <cmath>

#include "sim/core/TriangleMesh.h"

namespace figment::meshes {

// A rectangular grid in the plane spanned by `right` and `down` from `origin`,
// nu x nv quads, each split along the same diagonal; vertex (i, j) = i + j (nu + 1).
inline TriangleMesh grid(int nu, int nv, double width, double height, const Vec3& origin = Vec3::Zero(),
                         const Vec3& right = Vec3::UnitX(), const Vec3& down = -Vec3::UnitY()) {
  TriangleMesh mesh;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) mesh.vertices.push_back(origin + right * (width * i / nu) + down * (height * j / nv));
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const int a = i + j * (nu + 1), b = a + 1, c = a + nu + 1, d = c + 1;
      mesh.triangles.push_back({a, c, b});
      mesh.triangles.push_back({b, c, d});
    }
  return mesh;
}

// A 40 x 30 cm sheet of 24 x 18 quads (864 sections), curved like a sleeve's back:
// z = x^2 / 2.
inline TriangleMesh curvedSheet() {
  TriangleMesh sheet = grid(24, 18, 0.4, 0.3, Vec3(-0.2, 0.15, 0.0), Vec3::UnitX(), -Vec3::UnitY());
  for (Vec3& x : sheet.vertices) x.z() = 0.5 * x.x() * x.x();
  return sheet;
}

// A strip of equilateral triangles (edge a): `rows` + 1 straight rows of nodes across the
// strip, `rows` * a sqrt(3)/2 apart along `along`, each row `across` edges wide along
// `side`, odd rows shifted by a/2 (so the long edges zigzag and the two ends are straight).
// Node (i, j) = i + j (across + 1), i across, j along; its edges run at 0, 60 and 120
// degrees to the rows, so the mesh bends alike in every direction.
inline TriangleMesh equilateralStrip(int across, int rows, double a, const Vec3& origin = Vec3::Zero(),
                                     const Vec3& side = Vec3::UnitZ(), const Vec3& along = Vec3::UnitX()) {
  TriangleMesh mesh;
  const double spacing = a * std::sqrt(3.0) / 2.0;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= across; ++i)
      mesh.vertices.push_back(origin + side * (a * (i + 0.5 * (j % 2))) + along * (spacing * j));
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < across; ++i) {
      const int a0 = i + j * (across + 1), a1 = a0 + 1, b0 = a0 + across + 1, b1 = b0 + 1;
      if (j % 2 == 0) {  // row j+1 sits half an edge further along `side`
        mesh.triangles.push_back({a0, b0, a1});
        mesh.triangles.push_back({a1, b0, b1});
      } else {
        mesh.triangles.push_back({a0, b0, b1});
        mesh.triangles.push_back({a0, b1, a1});
      }
    }
  return mesh;
}

// A closed box from `lo` to `hi` (12 triangles), counter-clockwise seen from outside.
inline TriangleMesh box(const Vec3& lo, const Vec3& hi) {
  TriangleMesh mesh;
  for (int k = 0; k < 8; ++k)
    mesh.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  const int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& f : faces) {
    mesh.triangles.push_back({f[0], f[1], f[2]});
    mesh.triangles.push_back({f[0], f[2], f[3]});
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

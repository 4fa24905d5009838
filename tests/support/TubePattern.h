#pragma once
// A tube cut as two rectangular panels, front and back, placed either side of the body's
// axis and stitched along both sides: the smallest pattern that sews into a closed
// garment. What the sewing tests sew around a capsule, built in code so they need no
// pattern file.

#include "sim/pattern/UnsewnGarment.h"
#include "support/TestMeshes.h"

namespace figment::test {

// Panels `width` x `height` (m) of nu x nv quads, top at `top`, front at z = +gap/2 facing
// +z, back at z = -gap/2 facing -z; their side edges stitched front to back.
inline UnsewnGarment tubePattern(int nu, int nv, double width, double height, double top, double gap) {
  UnsewnGarment garment;
  const Vec3 frontOrigin(-width / 2, top, gap / 2), backOrigin(width / 2, top, -gap / 2);
  const TriangleMesh front = meshes::grid(nu, nv, width, height, frontOrigin, Vec3::UnitX(), -Vec3::UnitY());
  const TriangleMesh back = meshes::grid(nu, nv, width, height, backOrigin, -Vec3::UnitX(), -Vec3::UnitY());
  const int perPanel = static_cast<int>(front.vertices.size());
  for (int panel = 0; panel < 2; ++panel) {
    const TriangleMesh& mesh = panel == 0 ? front : back;
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) {
        garment.placed.vertices.push_back(mesh.vertices[i + j * (nu + 1)]);
        garment.flat.emplace_back(width * i / nu, -height * j / nv);
        garment.panelOf.push_back(panel);
      }
    for (const Triangle& t : mesh.triangles)
      garment.placed.triangles.push_back({t[0] + panel * perPanel, t[1] + panel * perPanel, t[2] + panel * perPanel});
  }
  garment.panelNames = {"front", "back"};
  // The front's right side (x = +w/2) meets the back's first column, its left side the
  // back's last column.
  for (int j = 0; j <= nv; ++j) {
    garment.seams.push_back({nu + j * (nu + 1), perPanel + j * (nu + 1)});
    garment.seamStitch.push_back(0);
    garment.seams.push_back({j * (nu + 1), perPanel + nu + j * (nu + 1)});
    garment.seamStitch.push_back(1);
  }
  return garment;
}

}  // namespace figment::test

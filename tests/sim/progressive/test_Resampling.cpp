// A garment at any number of sections: finer by subdivision then decimation, coarser by
// decimation alone; the shape and the perimeter stay.
#include "support/TestMeshes.h"
#include "sim/progressive/Resampling.h"

#include <gtest/gtest.h>

#include <stdexcept>

using namespace figment;

namespace {
// 40 x 30 cm, curved like a sleeve's back: 24 x 18 quads, 864 sections.
TriangleMesh curvedSheet() {
  TriangleMesh sheet = meshes::grid(24, 18, 0.4, 0.3, Vec3(-0.2, 0.15, 0.0), Vec3::UnitX(), -Vec3::UnitY());
  for (Vec3& x : sheet.vertices) x.z() = 0.5 * x.x() * x.x();
  return sheet;
}

Bounds boundsOf(const TriangleMesh& mesh) { return figment::boundsOf(mesh.vertices); }
}  // namespace

TEST(Resampling, AnyCountAboveOrBelowTheGarmentsKeepsItsShape) {
  const TriangleMesh sheet = curvedSheet();
  for (int target : {300, 864, 2000, 5000}) {
    const TriangleMesh out = resampled(sheet, target);
    EXPECT_NEAR(static_cast<double>(out.triangles.size()), target, 1.0) << target;
    EXPECT_NEAR(surfaceArea(out), surfaceArea(sheet), 0.01 * surfaceArea(sheet)) << target;
    const Bounds a = boundsOf(sheet), b = boundsOf(out);
    EXPECT_LT((a.min - b.min).norm(), 1e-9) << target;  // the corners stay
    EXPECT_LT((a.max - b.max).norm(), 1e-9) << target;
    for (const Vec3& x : out.vertices) EXPECT_NEAR(x.z(), 0.5 * x.x() * x.x(), 2e-3) << target;
  }
}

TEST(Resampling, NoTrianglesIsAnError) {
  EXPECT_THROW(resampled(curvedSheet(), 0), std::invalid_argument);
  EXPECT_THROW(resampled(TriangleMesh{}, 10), std::invalid_argument);
}

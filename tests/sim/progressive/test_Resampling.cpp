// A garment at any number of sections: finer by subdivision then decimation, coarser by
// decimation alone; the shape and the perimeter stay.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sim/progressive/Resampling.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
Bounds boundsOf(const TriangleMesh& mesh) {
  return figment::boundsOf(mesh.vertices);
}
}  // namespace

TEST(Resampling, AnyCountAboveOrBelowTheGarmentsKeepsItsShape) {
  const TriangleMesh sheet = meshes::curvedSheet();
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
  EXPECT_THROW(resampled(meshes::curvedSheet(), 0), std::invalid_argument);
  EXPECT_THROW(resampled(TriangleMesh{}, 10), std::invalid_argument);
}

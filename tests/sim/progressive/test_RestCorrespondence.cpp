// Drapes at two resolutions compared point by point: a garment's vertices found on a
// resampled copy's rest surface, and carried along when that copy moves.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <stdexcept>

#include "sim/progressive/Resampling.h"
#include "sim/progressive/RestCorrespondence.h"
#include "support/TestMeshes.h"

using namespace figment;

namespace {
// A rigid motion: 30 degrees about a tilted axis and a shift.
std::vector<Vec3> moved(const std::vector<Vec3>& points) {
  const Eigen::AngleAxisd turn(0.52, Vec3(1.0, 2.0, 0.5).normalized());
  std::vector<Vec3> out;
  for (const Vec3& p : points) out.push_back(turn * p + Vec3(0.1, -0.3, 0.2));
  return out;
}
}  // namespace

TEST(RestCorrespondence, OntoItselfEveryVertexIsCarriedExactly) {
  const TriangleMesh sheet = meshes::curvedSheet();
  const RestCorrespondence same(sheet, sheet);
  EXPECT_EQ(same.largestGap(), 0.0);
  const std::vector<Vec3> draped = moved(sheet.vertices), carried = same.carry(draped);
  ASSERT_EQ(carried.size(), draped.size());
  for (size_t i = 0; i < draped.size(); ++i) EXPECT_LT((carried[i] - draped[i]).norm(), 1e-12) << i;
}

TEST(RestCorrespondence, AResampledCopyMovedRigidlyCarriesTheGarmentAlong) {
  // The garment's vertices lie on the finer and the coarser copy's surface to within
  // their chords, and a rigid motion of the copy moves them rigidly (barycentric weights
  // are kept by any affine map).
  const TriangleMesh sheet = meshes::curvedSheet();
  for (int sections : {400, 2000}) {
    const TriangleMesh copy = resampled(sheet, sections);
    const RestCorrespondence onto(sheet, copy);
    EXPECT_LT(onto.largestGap(), 2e-3) << sections;
    const std::vector<Vec3> expected = moved(sheet.vertices), carried = onto.carry(moved(copy.vertices));
    double worst = 0.0;
    for (size_t i = 0; i < expected.size(); ++i) worst = std::max(worst, (carried[i] - expected[i]).norm());
    EXPECT_LT(worst, onto.largestGap() + 1e-12) << sections;
  }
}

TEST(RestCorrespondence, NoSectionsToMapOntoIsAnError) {
  EXPECT_THROW(RestCorrespondence(meshes::curvedSheet(), TriangleMesh{}), std::invalid_argument);
}

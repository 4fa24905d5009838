// A flared skirt round the box figure: its rings, its waistband just outside the waist's
// convex section (an outline offset by d grows by 2 pi d), its hem a skirt's length lower;
// each bad option refused naming it.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/garment/FlaredSkirt.h"
#include "support/BoxFigure.h"
#include "support/Refusal.h"

using namespace figment;

namespace {

TEST(FlaredSkirt, RingsRoundTheWaistDownToTheHem) {
  const FlaredSkirtOptions options;
  const FlaredSkirt skirt = makeFlaredSkirt(mannequin::figure(), options);
  EXPECT_EQ(skirt.mesh.vertices.size(), size_t((options.rows + 1) * options.columns));  // an open tube
  EXPECT_EQ(skirt.mesh.triangles.size(), size_t(2 * options.rows * options.columns));
  // The figure's torso runs from 0.8 m to its shoulders at 1.3 m.
  EXPECT_GT(skirt.waistHeight, 0.8);
  EXPECT_LT(skirt.waistHeight, 1.3);
  EXPECT_DOUBLE_EQ(skirt.hemHeight, skirt.waistHeight - options.length);
  // A polygon inscribed in the offset outline: not longer than that outline (the section's
  // perimeter plus 2 pi times the clearance). On the figure's box torso its 40 corners cut the
  // section's four, so it may be shorter than the section itself.
  EXPECT_GT(skirt.waistbandPerimeter, 0.0);
  EXPECT_LE(skirt.waistbandPerimeter, skirt.waistPerimeter + 2 * M_PI * options.waistClearance + 1e-9);
  for (const Vec3& v : skirt.mesh.vertices) {
    EXPECT_LE(v.y(), skirt.waistHeight + 1e-12);
    EXPECT_GE(v.y(), skirt.hemHeight - 1e-12);
  }
  EXPECT_GT(skirt.area, 0.0);
}

TEST(FlaredSkirt, RefusesEachBadOptionNamingIt) {
  const auto refusal = [](const FlaredSkirtOptions& options) { return test::refusal([&] { options.validate(); }); };
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({.length = 0}), "length = 0 must be > 0");
  EXPECT_EQ(refusal({.flare = -0.1}), "flare = -0.1 must be >= 0");
  EXPECT_EQ(refusal({.rows = 0}), "rows = 0 must be >= 1");
  EXPECT_EQ(refusal({.columns = 7}), "columns = 7 must be >= 8");
  EXPECT_THROW(makeFlaredSkirt(TriangleMesh{}), std::invalid_argument);
}

}  // namespace

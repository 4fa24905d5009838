// A body's description counts its parts by name, none where it has none.
#include <gtest/gtest.h>

#include "sim/drape/DrapeBody.h"

using namespace figment;

TEST(DrapeBody, ADescriptionCountsItsPartsByName) {
  const BodyDescription d{"mannequin", {{"capsule_volumes", 3}, {"radial_volumes", 11}}};
  EXPECT_EQ(d.count("capsule_volumes"), 3);
  EXPECT_EQ(d.count("radial_volumes"), 11);
  EXPECT_EQ(d.count("exact_parts"), 0);
  const DrapeBody none;
  EXPECT_EQ(none.description.kind, "none");
  EXPECT_FALSE(none.collider);
  EXPECT_FALSE(none.jointed);
}

// The faces of a coordIndex, the one walk over it that the guard's shape check and the node kit
// share.

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "guard/CoordIndexFaces.h"

TEST(CoordIndexFaces, FindsTheFirstIndexThatIsNeitherAVertexNorMinusOne) {
  const std::vector<int32_t> good{0, 1, 2, -1, 2, 3, 0};
  EXPECT_EQ(figment::guard::firstBadIndex(good.data(), int(good.size()), 4), -1);
  const std::vector<int32_t> large{0, 1, 2, -1, 2, 3, 2147483647, -1};
  EXPECT_EQ(figment::guard::firstBadIndex(large.data(), int(large.size()), 4), 6);
  const std::vector<int32_t> negative{0, 1, -2, -1};
  EXPECT_EQ(figment::guard::firstBadIndex(negative.data(), int(negative.size()), 4), 2);
  EXPECT_EQ(figment::guard::firstBadIndex(good.data(), int(good.size()), 3), 5) << "3 is past three points";
}

TEST(CoordIndexFaces, SplitsTheListAtEachNegativeIndexKeepingEmptyFaces) {
  const std::vector<int32_t> index{0, 1, 2, -1, -1, 2, 3};
  const std::vector<figment::guard::CoordIndexFace> faces =
      figment::guard::coordIndexFaces(index.data(), int(index.size()));
  ASSERT_EQ(faces.size(), 3u);
  EXPECT_EQ(faces[0].corners(), 3);
  EXPECT_EQ(faces[1].corners(), 0) << "two negatives in a row: an empty face";
  EXPECT_EQ(faces[2].first, 5);
  EXPECT_EQ(faces[2].end, 7) << "the last face ends with the list";
}

// Indexed shapes checked against the coordinates they use before anything draws them:
// one index of 2147483647 in a ClothingLayer made Coin allocate 2^31 normals (found by
// fuzzing figment-view, issue 15).

#include "nodes/CoordIndexFaces.h"
#include "nodes/FaceIndexCheck.h"
#include "support/SceneTestSupport.h"

#include <gtest/gtest.h>

#include <vector>

using namespace figment::test;

namespace {

// A square of four points drawn by `shape` with `coordIndex`; `extra` inside the shape.
std::string square(const std::string& shape, const std::string& coordIndex, const std::string& extra = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n"
         "  " + shape + " { coordIndex [ " + coordIndex + " ] " + extra + " }\n}\n";
}

std::string check(const std::string& text) {
  SceneRoot root = readString(text);
  EXPECT_TRUE(root) << text;
  return root ? figment::firstFaceIndexError(root.get()) : "not read";
}

class FaceIndexCheckTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

TEST(CoordIndexFaces, FindsTheFirstIndexThatIsNeitherAVertexNorMinusOne) {
  const std::vector<int32_t> good{0, 1, 2, -1, 2, 3, 0};
  EXPECT_EQ(figment::firstBadIndex(good.data(), int(good.size()), 4), -1);
  const std::vector<int32_t> large{0, 1, 2, -1, 2, 3, 2147483647, -1};
  EXPECT_EQ(figment::firstBadIndex(large.data(), int(large.size()), 4), 6);
  const std::vector<int32_t> negative{0, 1, -2, -1};
  EXPECT_EQ(figment::firstBadIndex(negative.data(), int(negative.size()), 4), 2);
  EXPECT_EQ(figment::firstBadIndex(good.data(), int(good.size()), 3), 5) << "3 is past three points";
}

TEST_F(FaceIndexCheckTest, PassesFaceSetsWithinTheirCoordinates) {
  EXPECT_EQ(check(square("ClothingLayer", "0 1 2 3 -1")), "");
  EXPECT_EQ(check(square("IndexedFaceSet", "0 1 2 -1, 0 2 3")), "") << "the last face needs no -1";
  EXPECT_EQ(check(square("IndexedLineSet", "0 1 2 3 0 -1")), "");
}

TEST_F(FaceIndexCheckTest, NamesTheNodeTheFieldAndTheValue) {
  EXPECT_EQ(check(square("DEF Shirt ClothingLayer", "0 1 2 2147483647 -1")),
            "ClothingLayer 'Shirt': coordIndex[3] = 2147483647 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(check(square("ClothingLayer", "0 1 2 -1 0 2 4 -1")),
            "ClothingLayer: coordIndex[6] = 4 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(check(square("ClothingLayer", "0 1 -2 3 -1")),
            "ClothingLayer: coordIndex[2] = -2 is neither a vertex nor the -1 that ends a face");
  EXPECT_EQ(check(square("DEF Faces IndexedFaceSet", "0 1 7 -1")),
            "IndexedFaceSet 'Faces': coordIndex[2] = 7 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(check(square("IndexedLineSet", "0 9 -1")),
            "IndexedLineSet: coordIndex[1] = 9 is not a vertex: the coordinates have 4 points");
}

TEST_F(FaceIndexCheckTest, CountsTheVertexPropertyWhenTheShapeHasOne) {
  const std::string own = "vertexProperty VertexProperty { vertex [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1 ] }";
  EXPECT_EQ(check(square("ClothingLayer", "0 1 4 -1", own)), "");
  EXPECT_EQ(check(square("ClothingLayer", "0 1 5 -1", own)),
            "ClothingLayer: coordIndex[2] = 5 is not a vertex: the coordinates have 5 points");
}

TEST_F(FaceIndexCheckTest, ChecksTheCoordinatesInPlaceWhereTheShapeIsDrawn) {
  // Two points in the first Separator, four after it: the layer after it is fine.
  const std::string text =
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n"
      "  Separator { Coordinate3 { point [ 0 0 0, 1 0 0 ] }  DEF Inner ClothingLayer { coordIndex [ 0 1 1 -1 ] } }\n"
      "  DEF Outer ClothingLayer { coordIndex [ 0 1 3 -1 ] }\n}\n";
  EXPECT_EQ(check(text), "");
  // A layer under a Switch that draws nothing is not drawn, so not checked.
  EXPECT_EQ(check(square("Switch { whichChild -1 ClothingLayer", "0 1 9 -1", "}")), "");
}

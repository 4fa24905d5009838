// The shape check's lines: the node by type and DEF name, the field and entry, and what the
// entry indexes past; counts with their nouns.
#include <Inventor/SoDB.h>
#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/shapes/IndexProblem.h"

using namespace figment::guard::shapes;

namespace {

class IndexProblemTest : public testing::Test {
 protected:
  static void SetUpTestSuite() { SoDB::init(); }
  void SetUp() override {
    faces_ = new SoIndexedFaceSet;
    faces_->ref();
  }
  void TearDown() override { faces_->unref(); }
  static void set(SoMFInt32& field, const std::vector<int32_t>& values) {
    field.setNum(0);  // setValues alone would keep a longer list's tail
    field.setValues(0, static_cast<int>(values.size()), values.data());
  }
  SoIndexedFaceSet* faces_ = nullptr;
};

TEST_F(IndexProblemTest, LabelsANodeByTypeAndName) {
  EXPECT_EQ(nodeLabel(*faces_), "IndexedFaceSet");
  faces_->setName("Faces");
  EXPECT_EQ(nodeLabel(*faces_), "IndexedFaceSet 'Faces'");
}

TEST_F(IndexProblemTest, CountsWithTheNounsPlural) {
  EXPECT_EQ(counted(1, "material"), "1 material");
  EXPECT_EQ(counted(3, "material"), "3 materials");
  EXPECT_EQ(counted(2, "vertex", "vertices"), "2 vertices");
  EXPECT_EQ(counted(0, "entry", "entries"), "0 entries");
}

TEST_F(IndexProblemTest, NamesTheFirstEntryPastWhatItIndexes) {
  set(faces_->coordIndex, {0, 1, 2, -1, 0, 2, 4, -1});
  const Indexed points{4, "point", "the coordinates have 4 points"};
  EXPECT_EQ(indexProblem(*faces_, "coordIndex", faces_->coordIndex, points),
            "IndexedFaceSet: coordIndex[6] = 4 is not a point: the coordinates have 4 points");
  set(faces_->coordIndex, {0, 1, -2});
  EXPECT_EQ(indexProblem(*faces_, "coordIndex", faces_->coordIndex, points),
            "IndexedFaceSet: coordIndex[2] = -2 is neither a point nor the -1 that ends a face");
  set(faces_->coordIndex, {0, 1, 3, -1});
  EXPECT_EQ(indexProblem(*faces_, "coordIndex", faces_->coordIndex, points), "");
}

TEST_F(IndexProblemTest, ShortIndexSaysHowManyEntriesForWhat) {
  set(faces_->materialIndex, {0, 1});
  EXPECT_EQ(shortIndexProblem(*faces_, "materialIndex", faces_->materialIndex, 3, "3 faces"),
            "IndexedFaceSet: materialIndex has 2 entries for 3 faces");
  EXPECT_EQ(shortIndexProblem(*faces_, "materialIndex", faces_->materialIndex, 2, "2 faces"), "");
}

TEST_F(IndexProblemTest, GivenAndFaceCountReadTheIndexAsCoinDoes) {
  set(faces_->materialIndex, {-1});
  EXPECT_FALSE(given(faces_->materialIndex));  // a first entry below 0: absent
  set(faces_->materialIndex, {0});
  EXPECT_TRUE(given(faces_->materialIndex));
  set(faces_->coordIndex, {0, 1, 2, -1, 2, 3, 0});  // the last face ends at the end
  EXPECT_EQ(faceCount(faces_->coordIndex), 2);
}

}  // namespace

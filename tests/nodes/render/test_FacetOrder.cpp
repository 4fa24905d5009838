// Which facets a ClothingLayer draws over what lies beneath, and in which order.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "nodes/render/FacetOrder.h"

using figment::OrderedFacet;
using figment::ViewPoint;

namespace {
// A camera on +z at distance 5 looking down -z.
ViewPoint fromFront(bool perspective = true) {
  ViewPoint view;
  view.perspective = perspective;
  view.eye = SbVec3f(0, 0, 5);
  view.direction = SbVec3f(0, 0, -1);
  view.toCamera.setTranslate(SbVec3f(0, 0, -5));
  return view;
}
}  // namespace

TEST(FacetOrder, FacetsFacingTheEyeAreDrawnOverTheRest) {
  // Counter-clockwise seen from +z (faces the eye), and the same square reversed.
  const SbVec3f points[] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const int32_t index[] = {0, 1, 2, 3, -1, 3, 2, 1, 0, -1};
  for (bool perspective : {true, false}) {
    const auto facets = figment::orderFacets(points, 4, index, 10, fromFront(perspective));
    ASSERT_EQ(facets.size(), 2u);
    for (const OrderedFacet& f : facets) EXPECT_EQ(f.facesViewer, f.firstIndex == 0) << "perspective " << perspective;
  }
  ViewPoint clockwise = fromFront();
  clockwise.clockwise = true;
  for (const OrderedFacet& f : figment::orderFacets(points, 4, index, 10, clockwise))
    EXPECT_EQ(f.facesViewer, f.firstIndex == 5) << "CLOCKWISE ordering swaps the front";
}

TEST(FacetOrder, PerspectiveJudgesEachFacetFromTheEye) {
  // A facet at x = 3 facing +x: the eye on the z axis lies on its -x side, so it faces
  // away; an orthographic view straight down -z sees it edge-on, which counts as facing
  // (only facets facing substantially away keep the depth test).
  const SbVec3f points[] = {{3, 0, 0}, {3, 0, -1}, {3, 1, -1}, {3, 1, 0}};
  const int32_t index[] = {0, 1, 2, 3};
  const auto perspective = figment::orderFacets(points, 4, index, 4, fromFront(true));
  ASSERT_EQ(perspective.size(), 1u);
  EXPECT_FALSE(perspective[0].facesViewer);
  const auto orthographic = figment::orderFacets(points, 4, index, 4, fromFront(false));
  EXPECT_TRUE(orthographic[0].facesViewer);
}

TEST(FacetOrder, FacetsAreSortedFarToNearByTheirCentres) {
  // Three triangles at z = 0, -2 and 1, listed in that order.
  const SbVec3f points[] = {{0, 0, 0},  {1, 0, 0}, {0, 1, 0}, {0, 0, -2}, {1, 0, -2},
                            {0, 1, -2}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  const int32_t index[] = {0, 1, 2, -1, 3, 4, 5, -1, 6, 7, 8, -1};
  const auto facets = figment::orderFacets(points, 9, index, 12, fromFront());
  ASSERT_EQ(facets.size(), 3u);
  EXPECT_EQ(facets[0].firstIndex, 4);  // z = -2, farthest
  EXPECT_EQ(facets[1].firstIndex, 0);
  EXPECT_EQ(facets[2].firstIndex, 8);  // z = 1, nearest
}

TEST(FacetOrder, FacetsWithBadIndicesOrTooFewCornersAreSkipped) {
  const SbVec3f points[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const int32_t index[] = {0, 1, 7, -1, 0, 1, -1, 0, 1, 2};  // out of range; two corners; good (no -1)
  const auto facets = figment::orderFacets(points, 3, index, 10, fromFront());
  ASSERT_EQ(facets.size(), 1u);
  EXPECT_EQ(facets[0].firstIndex, 7);
  EXPECT_EQ(facets[0].corners, 3);
}

namespace {
// An open tube about the y axis (a skirt): `around` quads round, radius 1, 1 high,
// counter-clockwise seen from outside unless `reversed`.
std::vector<int32_t> tube(std::vector<SbVec3f>& points, int around, bool reversed) {
  std::vector<int32_t> index;
  for (int i = 0; i < around; ++i) {
    const float angle = 2.0f * float(M_PI) * float(i) / float(around);
    points.emplace_back(std::sin(angle), 0.0f, std::cos(angle));
    points.emplace_back(std::sin(angle), 1.0f, std::cos(angle));
  }
  for (int i = 0; i < around; ++i) {
    const int j = (i + 1) % around;
    std::vector<int32_t> quad = {2 * i, 2 * j, 2 * j + 1, 2 * i + 1};  // outward: (bottom i, bottom j, top j, top i)
    if (reversed) std::reverse(quad.begin(), quad.end());
    index.insert(index.end(), quad.begin(), quad.end());
    index.push_back(-1);
  }
  return index;
}
}  // namespace

TEST(FacetOrder, TheOutsideOfAGarmentIsFoundWhateverItsWinding) {
  for (bool reversed : {false, true}) {
    std::vector<SbVec3f> points;
    const std::vector<int32_t> index = tube(points, 24, reversed);
    const auto facets = figment::describeFacets(points.data(), int(points.size()), index.data(), int(index.size()));
    ASSERT_EQ(facets.size(), 24u);
    EXPECT_EQ(figment::outsideWinding(facets),
              reversed ? figment::Winding::CLOCKWISE : figment::Winding::COUNTERCLOCKWISE);
  }
}

TEST(FacetOrder, AFlatSheetLeavesTheWindingToTheShapeHints) {
  // A 4 x 4 grid of quads in the plane z = 0: both sides alike.
  std::vector<SbVec3f> points;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x) points.emplace_back(float(x), float(y), 0.0f);
  std::vector<int32_t> index;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) index.insert(index.end(), {5 * y + x, 5 * y + x + 1, 5 * y + x + 6, 5 * y + x + 5, -1});
  const auto facets = figment::describeFacets(points.data(), int(points.size()), index.data(), int(index.size()));
  EXPECT_EQ(figment::outsideWinding(facets), figment::Winding::UNDECIDED);
  EXPECT_EQ(figment::outsideWinding({}), figment::Winding::UNDECIDED);
}

// Indexed shapes checked against the coordinates they use before anything draws them:
// one index of 2147483647 in a ClothingLayer made Coin allocate 2^31 normals (found by
// fuzzing figment-view, issue 15).

#include <gtest/gtest.h>

#include "guard/FaceIndexCheck.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

// A square of four points drawn by `shape` with `coordIndex`; `extra` inside the shape.
std::string square(const std::string& shape, const std::string& coordIndex, const std::string& extra = "") {
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n"
         "  " +
         shape + " { coordIndex [ " + coordIndex + " ] " + extra + " }\n}\n";
}

std::string check(const std::string& text) {
  SceneRoot root = readString(text);
  EXPECT_TRUE(root) << text;
  return root ? figment::guard::checkShapes(root.get()) : "not read";
}

class FaceIndexCheckTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

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

namespace {

// A scene of `body` after four points in a Coordinate3 (header added).
std::string onFourPoints(const std::string& body) {
  return "#Inventor V2.1 ascii\nSeparator {\n  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n  " + body +
         "\n}\n";
}

const std::string kTwoTriangles = "coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ]";
const std::string kVrmlSquare = "coord VRMLCoordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }";

}  // namespace

// Each of these crashed figment-view (SIGSEGV) before the check: Coin reads the materials,
// normals and texture coordinates at what the shape's indices say.
TEST_F(FaceIndexCheckTest, ChecksTheIndicesOfMaterialsNormalsAndTextureCoordinates) {
  const std::string twoMaterials = "Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n  ";
  EXPECT_EQ(check(onFourPoints(twoMaterials + "MaterialBinding { value PER_FACE_INDEXED }\n  IndexedFaceSet { " +
                               kTwoTriangles + " materialIndex [ 1, 0 ] }")),
            "");
  EXPECT_EQ(check(onFourPoints(twoMaterials + "MaterialBinding { value PER_FACE_INDEXED }\n  IndexedFaceSet { " +
                               kTwoTriangles + " materialIndex [ 0, 70000000 ] }")),
            "IndexedFaceSet: materialIndex[1] = 70000000 is not a material: the shape has 2 materials");
  EXPECT_EQ(check(onFourPoints("NormalBinding { value PER_VERTEX_INDEXED } Normal { vector [ 0 0 1 ] }\n  "
                               "IndexedFaceSet { " +
                               kTwoTriangles + " normalIndex [ 0, 0, 0, -1, 0, 2000000000, 0, -1 ] }")),
            "IndexedFaceSet: normalIndex[5] = 2000000000 is not a normal: the shape has 1 normal");
  EXPECT_EQ(
      check(onFourPoints("Texture2 { image 1 1 3 0xff0000 } TextureCoordinate2 { point [ 0 0, 1 0, 1 1 ] }\n  "
                         "IndexedLineSet { coordIndex [ 0, 1, 2 ] textureCoordIndex [ 0, 1, 3 ] }")),
      "IndexedLineSet: textureCoordIndex[2] = 3 is not a texture coordinate: the shape has 3 texture coordinates");
  // Without a texture, texture coordinates are not read.
  EXPECT_EQ(check(onFourPoints("TextureCoordinate2 { point [ 0 0 ] }\n  IndexedFaceSet { " + kTwoTriangles +
                               " textureCoordIndex [ 0, 9, 0, -1 ] }")),
            "");
  // An index runs along the vertices or the faces, however long it is.
  EXPECT_EQ(check(onFourPoints(twoMaterials + "MaterialBinding { value PER_FACE_INDEXED }\n  IndexedFaceSet { " +
                               kTwoTriangles + " materialIndex [ 1 ] }")),
            "IndexedFaceSet: materialIndex has 1 entry for 2 faces");
  // A binding per vertex, indexed, without an index of its own reads coordIndex.
  EXPECT_EQ(
      check(onFourPoints("Normal { vector [ 0 0 1, 0 0 1, 0 0 1 ] }\n  IndexedFaceSet { " + kTwoTriangles + " }")),
      "IndexedFaceSet: coordIndex[6] = 3 is not a normal: the shape has 3 normals, and coordIndex indexes them "
      "as the binding is PER_VERTEX_INDEXED and normalIndex is empty");
  // A VertexProperty's own colours and binding count where it has them.
  EXPECT_EQ(
      check(onFourPoints(
          "IndexedFaceSet { " + kTwoTriangles +
          " vertexProperty VertexProperty { orderedRGBA [ 0xff0000ff ] materialBinding PER_VERTEX_INDEXED } }")),
      "IndexedFaceSet: coordIndex[1] = 1 is not a material: the VertexProperty has 1 material, and coordIndex indexes "
      "them as the binding is PER_VERTEX_INDEXED and materialIndex is empty");
}

TEST_F(FaceIndexCheckTest, ChecksWhatCountedShapesDrawAgainstTheCoordinates) {
  EXPECT_EQ(check(onFourPoints("FaceSet { numVertices [ 3 ] } LineSet { numVertices [ 2, 2 ] } PointSet { }")), "");
  EXPECT_EQ(check(onFourPoints("DEF Faces FaceSet { numVertices [ 3, 2000000000 ] }")),
            "FaceSet 'Faces': numVertices draw 2000000003 vertices from startIndex 0: the coordinates have 4 points");
  EXPECT_EQ(check(onFourPoints("TriangleStripSet { startIndex 2 numVertices [ 3 ] }")),
            "TriangleStripSet: numVertices draw 3 vertices from startIndex 2: the coordinates have 4 points");
  EXPECT_EQ(check(onFourPoints("TriangleStripSet { startIndex 2000000000 numVertices [ 3 ] }")),
            "TriangleStripSet: startIndex = 2000000000 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(check(onFourPoints("QuadMesh { verticesPerRow 50000 verticesPerColumn 50000 }")),
            "QuadMesh: verticesPerRow x verticesPerColumn draw 2500000000 vertices from startIndex 0: the coordinates "
            "have 4 points");
  EXPECT_EQ(check(onFourPoints("PointSet { numPoints 5 }")),
            "PointSet: numPoints draw 5 vertices from startIndex 0: the coordinates have 4 points");
}

TEST_F(FaceIndexCheckTest, ChecksVrmlShapesAgainstTheirOwnData) {
  const auto shape = [](const std::string& geometry) {
    return onFourPoints("VRMLShape { geometry " + geometry + " }");
  };
  EXPECT_EQ(check(shape("VRMLIndexedFaceSet { " + kVrmlSquare + " " + kTwoTriangles +
                        " color VRMLColor { color [ 1 0 0, 0 1 0 ] } colorPerVertex FALSE }")),
            "");
  // Drawn with a warning before the check.
  EXPECT_EQ(check(shape("VRMLIndexedFaceSet { " + kVrmlSquare + " coordIndex [ 0, 1, 2000000000, -1 ] }")),
            "VRMLIndexedFaceSet: coordIndex[2] = 2000000000 is not a point: the VRMLCoordinate has 4 points");
  // Crashed figment-view (SIGSEGV).
  EXPECT_EQ(check(shape("VRMLIndexedFaceSet { " + kVrmlSquare + " " + kTwoTriangles +
                        " color VRMLColor { color [ 1 0 0 ] } colorIndex [ 0, 2000000000, 0, -1, 0, 0, 0, -1 ] }")),
            "VRMLIndexedFaceSet: colorIndex[1] = 2000000000 is not a color: the VRMLColor has 1 color");
  EXPECT_EQ(
      check(shape("VRMLIndexedFaceSet { " + kVrmlSquare + " " + kTwoTriangles +
                  " color VRMLColor { color [ 1 0 0 ] } colorPerVertex FALSE }")),
      "VRMLIndexedFaceSet: the VRMLColor has 1 color for 2 faces (colorPerVertex is FALSE and colorIndex is empty)");
  EXPECT_EQ(
      check(shape("VRMLIndexedLineSet { " + kVrmlSquare +
                  " coordIndex [ 0, 1, 2, 3 ] color VRMLColor { "
                  "color [ 1 0 0, 0 1 0 ] } }")),
      "VRMLIndexedLineSet: coordIndex[2] = 2 is not a color: the VRMLColor has 2 colors, and coordIndex indexes them "
      "as colorPerVertex is TRUE and colorIndex is empty");
  EXPECT_EQ(check(shape("VRMLPointSet { " + kVrmlSquare + " color VRMLColor { color [ 1 0 0 ] } }")),
            "VRMLPointSet: the VRMLColor has 1 color for 4 points: one for each");
  EXPECT_EQ(check(shape("VRMLElevationGrid { xDimension 3000 zDimension 3000 height [ 0, 0, 0, 0 ] }")),
            "VRMLElevationGrid: height has 4 values for the 9000000 vertices of its 3000 x 3000 grid");
  EXPECT_EQ(check(shape("VRMLElevationGrid { xDimension 2 zDimension 2 height [ 0, 0, 0, 0 ] }")), "");
}

// Each crashed figment-view (SIGSEGV) before the check, but for the short knot vector, which
// ended in std::bad_array_new_length.
TEST_F(FaceIndexCheckTest, ChecksNurbsControlPointsAndKnots) {
  const std::string knots = " uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ]";
  EXPECT_EQ(check(onFourPoints("NurbsSurface { numUControlPoints 2 numVControlPoints 2" + knots + " }")), "");
  EXPECT_EQ(check(onFourPoints("NurbsSurface { numUControlPoints 3 numVControlPoints 2"
                               " uKnotVector [ 0, 0, 0.5, 1, 1 ] vKnotVector [ 0, 0, 1, 1 ] }")),
            "NurbsSurface: numUControlPoints x numVControlPoints make 6 control points: the coordinates have 4 points");
  EXPECT_EQ(check(onFourPoints("NurbsSurface { numUControlPoints 2 numVControlPoints 2"
                               " uKnotVector [ 0, 0, 1, 1 ] vKnotVector [ 0 ] }")),
            "NurbsSurface: vKnotVector has 1 knot for 2 control points: it needs the control points plus the order, at "
            "least 2");
  EXPECT_EQ(check(onFourPoints(
                "IndexedNurbsSurface { numUControlPoints 2 numVControlPoints 2 coordIndex [ 0, 1, 2, 2000000000 ]" +
                knots + " }")),
            "IndexedNurbsSurface: coordIndex[3] = 2000000000 is not a vertex: the coordinates have 4 points");
  EXPECT_EQ(
      check(onFourPoints("IndexedNurbsSurface { numUControlPoints 2 numVControlPoints 2 coordIndex [ 0, 1, 2 ]" +
                         knots + " }")),
      "IndexedNurbsSurface: coordIndex has 3 entries for numUControlPoints x numVControlPoints = 4 control points");
  EXPECT_EQ(check(onFourPoints("NurbsCurve { numControlPoints 5 knotVector [ 0, 0, 0.3, 0.5, 0.7, 1, 1 ] }")),
            "NurbsCurve: numControlPoints make 5 control points: the coordinates have 4 points");
}

TEST_F(FaceIndexCheckTest, ChecksMarkersAreCoinsMarkers) {
  EXPECT_EQ(check(onFourPoints("MarkerSet { markerIndex [ 0, 5, -1 ] }")), "");
  EXPECT_EQ(
      check(onFourPoints("MarkerSet { markerIndex [ 2000000000 ] }")),
      "MarkerSet: markerIndex[0] = 2000000000 is not a marker: there are 90 (and -1, none)");  // crashed figment-view
  EXPECT_EQ(check(onFourPoints("IndexedMarkerSet { coordIndex [ 0, 1 ] markerIndex [ 0, 90 ] }")),
            "IndexedMarkerSet: markerIndex[1] = 90 is not a marker: there are 90 (and -1, none)");
  // Coin skips -1 only; 4000000000 is read as -294967296 (crashed; found by fuzz_scene).
  EXPECT_EQ(check(onFourPoints("MarkerSet { markerIndex [ 0, -2 ] }")),
            "MarkerSet: markerIndex[1] = -2 is not a marker: there are 90 (and -1, none)");
  EXPECT_EQ(check(onFourPoints("MarkerSet { markerIndex [ 4000000000 ] }")),
            "MarkerSet: markerIndex[0] = -294967296 is not a marker: there are 90 (and -1, none)");
}

// In VRML 1.0, PER_VERTEX means per vertex of the shape: Coin reads such materials through
// coordIndex (a 20,000-point face set read 80 KB past its one material before).
TEST_F(FaceIndexCheckTest, ReadsAVrml1PerVertexBindingThroughCoordIndex) {
  const std::string scene =
      "#VRML V1.0 ascii\nSeparator {\n  MaterialBinding { value PER_VERTEX }\n"
      "  Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n"
      "  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n  IndexedFaceSet { coordIndex [ ";
  EXPECT_EQ(check(scene + "0, 1, 1, -1 ] }\n}\n"), "");
  EXPECT_EQ(check(scene + "0, 1, 3, -1 ] }\n}\n"),
            "IndexedFaceSet: coordIndex[2] = 3 is not a material: the shape has 2 materials, and coordIndex indexes "
            "them as a VRML 1.0 binding PER_VERTEX does");
}

// Data bound per vertex, part or face are taken one after another: Coin read past one
// material for a 20,000-vertex FaceSet bound PER_VERTEX without a word before.
TEST_F(FaceIndexCheckTest, CountsDataTakenOneAfterAnotherAgainstWhatTheyAreFor) {
  const std::string oneMaterial = "Material { diffuseColor [ 1 0 0 ] }\n  ";
  EXPECT_EQ(check(onFourPoints(oneMaterial + "MaterialBinding { value PER_VERTEX }\n  FaceSet { numVertices [ 4 ] }")),
            "FaceSet: the shape has 1 material for its 4 vertices (bound PER_VERTEX, one each)");
  EXPECT_EQ(check(onFourPoints(oneMaterial + "MaterialBinding { value PER_FACE }\n  IndexedFaceSet { " + kTwoTriangles +
                               " }")),
            "IndexedFaceSet: the shape has 1 material for its 2 faces (bound PER_FACE, one each)");
  // A line set's parts are its segments; PER_FACE_INDEXED without an index counts faces.
  EXPECT_EQ(check(onFourPoints("Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n  MaterialBinding { value PER_PART }\n"
                               "  IndexedLineSet { coordIndex [ 0, 1, 2, 3 ] }")),
            "IndexedLineSet: the shape has 2 materials for its 3 parts (bound PER_PART, one each)");
  EXPECT_EQ(check(onFourPoints(oneMaterial + "MaterialBinding { value PER_FACE_INDEXED }\n  IndexedFaceSet { " +
                               kTwoTriangles + " }")),
            "IndexedFaceSet: the shape has 1 material for its 2 faces (bound PER_FACE, one each)");
  // A shape without indices takes an indexed binding as the plain one.
  EXPECT_EQ(check(onFourPoints("Normal { vector [ 0 0 1 ] }\n  LineSet { numVertices [ 4 ] }")),
            "LineSet: the shape has 1 normal for its 4 vertices (bound PER_VERTEX, one each)");
  EXPECT_EQ(
      check(onFourPoints("Texture2 { image 1 1 3 0xff0000 } TextureCoordinate2 { point [ 0 0 ] }\n  PointSet { }")),
      "PointSet: the shape has 1 texture coordinate for its 4 vertices (bound PER_VERTEX, one each)");
  // Enough of each.
  EXPECT_EQ(check(onFourPoints("Material { diffuseColor [ 1 0 0, 0 1 0 ] }\n  MaterialBinding { value PER_FACE }\n"
                               "  FaceSet { numVertices [ 3 ] } TriangleStripSet { numVertices [ 4 ] }")),
            "");
}

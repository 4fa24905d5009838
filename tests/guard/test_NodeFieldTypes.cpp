// Node fields hold the node types they take: Coin reads any node into an SFNode or MFNode
// field, and its VRML97 shapes cast what they hold (a VRMLIndexedLineSet whose coord was a
// VRMLMaterial crashed figment-view); a read scene is checked before any action.

#include <Inventor/VRMLnodes/SoVRMLMaterial.h>
#include <Inventor/VRMLnodes/SoVRMLText.h>
#include <gtest/gtest.h>

#include <string>

#include "guard/NodeFieldTypes.h"
#include "guard/SceneExpansion.h"
#include "support/SceneTestSupport.h"

using namespace figment::guard;

namespace {

// The problem firstMistypedNodeField finds in the Inventor scene `body` (header added).
std::string problemIn(const std::string& body) {
  figment::test::initCoin();
  const figment::test::SceneRoot root = figment::test::readString("#Inventor V2.1 ascii\n" + body + "\n");
  return root ? firstMistypedNodeField(root.get()) : "unreadable: " + body;
}

const std::string kCoordinates = "VRMLCoordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] }";

}  // namespace

TEST(NodeFieldTypes, AcceptsWhatEachFieldTakes) {
  EXPECT_EQ(problemIn("VRMLShape { appearance VRMLAppearance { material VRMLMaterial { } }\n"
                      "  geometry VRMLIndexedFaceSet { coord " +
                      kCoordinates +
                      " coordIndex [ 0, 1, 2, -1 ]\n"
                      "    color VRMLColor { color [ 1 0 0 ] } normal VRMLNormal { vector [ 0 0 1 ] } } }"),
            "");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLText { string \"A\" fontStyle VRMLFontStyle { } } }"), "");
  // A shape of either kind draws as a VRMLShape's geometry; a Separator is a shape's place.
  EXPECT_EQ(problemIn("VRMLShape { geometry Cube { } }"), "");
  EXPECT_EQ(problemIn("IndexedFaceSet { vertexProperty VertexProperty { vertex [ 0 0 0, 1 0 0, 0 1 0 ] }"
                      " coordIndex [ 0, 1, 2, -1 ] }"),
            "");
  EXPECT_EQ(problemIn("SceneTexture2 { scene Separator { Cube { } } } Cube { }"), "");  // takes any node
}

TEST(NodeFieldTypes, NamesTheNodeTheFieldAndWhatItHolds) {
  // Each crashed figment-view (SIGSEGV) before the check.
  EXPECT_EQ(problemIn("VRMLShape { geometry DEF Lines VRMLIndexedLineSet { coord VRMLMaterial { }"
                      " coordIndex [ 0, 1, -1 ] } }"),
            "VRMLIndexedLineSet 'Lines': coord holds a VRMLMaterial, where a VRMLCoordinate belongs");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLPointSet { coord VRMLMaterial { } } }"),
            "VRMLPointSet: coord holds a VRMLMaterial, where a VRMLCoordinate belongs");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLText { string \"ab\" fontStyle DEF Red VRMLMaterial { } } }"),
            "VRMLText: fontStyle holds a VRMLMaterial 'Red', where a VRMLFontStyle belongs");
  EXPECT_EQ(
      problemIn("VRMLShape { geometry VRMLIndexedFaceSet { coord VRMLMaterial { } coordIndex [ 0, 1, 2, -1 ] } }"),
      "VRMLIndexedFaceSet: coord holds a VRMLMaterial, where a VRMLCoordinate belongs");
  // Coin casts these as well; they read memory of another type.
  EXPECT_EQ(problemIn("VRMLShape { appearance VRMLMaterial { } geometry VRMLBox { } }"),
            "VRMLShape: appearance holds a VRMLMaterial, where a VRMLAppearance belongs");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLIndexedFaceSet { coord " + kCoordinates +
                      " coordIndex [ 0, 1, 2, -1 ] color VRMLNormal { } } }"),
            "VRMLIndexedFaceSet: color holds a VRMLNormal, where a VRMLColor belongs");
  EXPECT_EQ(problemIn("VRMLSound { source VRMLMaterial { } }"),
            "VRMLSound: source holds a VRMLMaterial, where a VRMLAudioClip or a VRMLMovieTexture belongs");
  EXPECT_EQ(problemIn("ShaderProgram { shaderObject [ VertexShader { }, Cube { } ] }"),
            "ShaderProgram: shaderObject[1] holds a Cube, where a ShaderObject belongs");
  EXPECT_EQ(problemIn("IndexedFaceSet { vertexProperty Material { } coordIndex [ 0, 1, 2, -1 ] }"),
            "IndexedFaceSet: vertexProperty holds a Material, where a VertexProperty belongs");
  EXPECT_EQ(problemIn("VRMLShape { geometry VRMLMaterial { } }"),
            "VRMLShape: geometry holds a VRMLMaterial, where a Shape belongs");
}

TEST(NodeFieldTypes, FindsFieldsHeldDeepInTheGraph) {
  // Under a group, in a field of a node in a field.
  EXPECT_EQ(problemIn("Separator { Group { VRMLShape { appearance VRMLAppearance {"
                      " material DEF Wrong VRMLImageTexture { } } } } }"),
            "VRMLAppearance: material holds a VRMLImageTexture 'Wrong', where a VRMLMaterial belongs");
}

// A chain of fields far deeper than Coin's stack allows is checked without recursion.
TEST(NodeFieldTypes, WalksALongChainWithoutRecursion) {
  SoDB::init();
  auto* root = new SoSeparator;
  root->ref();
  SoNode* held = new SoVRMLMaterial;
  for (int i = 0; i < 100'000; ++i) {
    auto* text = new SoVRMLText;
    text->fontStyle = held;
    held = text;
  }
  root->addChild(held);
  EXPECT_EQ(firstMistypedNodeField(root), "VRMLText: fontStyle holds a VRMLText, where a VRMLFontStyle belongs");
  unrefWithoutRecursion(root);  // Coin's unref would recurse 100,000 levels
}

// A scene with every FIGMENT node type, written with SoWriteAction and read again,
// comes back with the same nodes and field values.

#include "nodes/ClothEngine.h"
#include "nodes/ClothingLayer.h"
#include "nodes/MeshFile.h"
#include "SceneTestSupport.h"

#include <Inventor/SoFullPath.h>
#include <Inventor/fields/SoSFNode.h>
#include <Inventor/lists/SoPathList.h>

#include <gtest/gtest.h>

using namespace figment::test;

namespace {

// Every node of the graph in traversal order, inactive Switch children included.
std::vector<SoNode*> nodesOf(SoNode* root) {
  SoSearchAction search;
  search.setType(SoNode::getClassTypeId(), TRUE);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::vector<SoNode*> nodes;
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    nodes.push_back(static_cast<SoFullPath*>(search.getPaths()[i])->getTail());
  return nodes;
}

void expectSameFields(SoFieldContainer* a, SoFieldContainer* b, const std::string& what) {
  SoFieldList fields;
  a->getFields(fields);
  for (int i = 0; i < fields.getLength(); ++i) {
    SbName name;
    a->getFieldName(fields[i], name);
    SoField* other = b->getField(name);
    ASSERT_NE(other, nullptr) << what << "." << name.getString();
    if (fields[i]->isOfType(SoSFNode::getClassTypeId())) {
      // Different graphs hold different nodes: compare what they are.
      SoNode* x = static_cast<SoSFNode*>(fields[i])->getValue();
      SoNode* y = static_cast<SoSFNode*>(other)->getValue();
      ASSERT_EQ(x == nullptr, y == nullptr) << what << "." << name.getString();
      if (x) {
        EXPECT_EQ(x->getTypeId(), y->getTypeId()) << what << "." << name.getString();
        EXPECT_EQ(x->getName(), y->getName()) << what << "." << name.getString();
      }
      continue;
    }
    EXPECT_TRUE(fields[i]->isSame(*other)) << what << "." << name.getString();
  }
}

}  // namespace

TEST(RoundTrip, EveryNodeTypeComesBackWithItsFieldValues) {
  initCoin();
  TempDir dir;
  dir.file("cube.obj", cubeObj());
  const Grid g = grid(4, 0.6, 1.05, 0.5, 0.5);
  const std::string path = dir.file(
      "scene.iv",
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  DEF Body MeshFile { fileName \"cube.obj\" metresPerUnit 1 upAxis Y exclude \"nothing\" }\n"
      "  Switch { whichChild -1  DEF Pattern Coordinate3 { point [ " + g.points + " ] } }\n"
      "  Coordinate3 { point = DEF Drape ClothEngine {\n"
      "    restPoints = USE Pattern.point\n"
      "    coordIndex [ " + g.coordIndex + " ]\n"
      "    body USE Body\n"
      "    thickness 0.0007 density 250 youngsModulus 2e6 poissonRatio 0.25 timeStep 1e-4\n"
      "    maxTime 0.01 restSpeed 0.02 restWindow 0.1 gravity 0 -9 0 airResistance 2\n"
      "    friction 0.3 clearance 0.002 strainRateDamping 2e-4\n"
      "  } . positions }\n"
      "  DEF Layer ClothingLayer { coordIndex [ " + g.coordIndex + " ] masked TRUE }\n"
      "}\n");
  SceneRoot first = readFile(path);
  ASSERT_TRUE(first);
  const std::string text = writeString(first.get());
  // Written next to the original, so the MeshFile finds cube.obj the same way.
  SceneRoot second = readFile(dir.file("written.iv", text));
  ASSERT_TRUE(second) << text;

  const std::vector<SoNode*> a = nodesOf(first.get()), b = nodesOf(second.get());
  ASSERT_EQ(a.size(), b.size()) << text;
  for (size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i]->getTypeId(), b[i]->getTypeId()) << i;
    expectSameFields(a[i], b[i], a[i]->getTypeId().getName().getString());
  }
  const std::vector<ClothEngine*> ea = figment::findClothEngines(first.get());
  const std::vector<ClothEngine*> eb = figment::findClothEngines(second.get());
  ASSERT_EQ(ea.size(), 1u);
  ASSERT_EQ(eb.size(), 1u);
  EXPECT_STREQ(eb[0]->getName().getString(), "Drape");
  expectSameFields(ea[0], eb[0], "ClothEngine");
  // The connections survive, not only the values they carried.
  SoField* master = nullptr;
  ASSERT_TRUE(eb[0]->restPoints.getConnectedField(master));
  EXPECT_STREQ(static_cast<SoNode*>(master->getContainer())->getName().getString(), "Pattern");
  EXPECT_EQ(eb[0]->body.getValue(), find<MeshFile>(second.get(), "Body"));
}

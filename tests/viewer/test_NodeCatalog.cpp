// --list-nodes' catalogue: FIGMENT's types and their fields from Coin's field data.

#include <Inventor/SoDB.h>
#include <Inventor/engines/SoEngine.h>
#include <Inventor/nodes/SoNode.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "nodes/Init.h"
#include "viewer/NodeCatalog.h"

using namespace figment::viewer;

TEST(NodeCatalog, FindsTheTypesARegistrationAdds) {
  // A registration of one node type and one engine type (abstract types, enough for
  // Coin's type tree): exactly those two are found, sorted by name.
  SoDB::init();
  const std::vector<SoType> added = typesAddedBy([] {
    SoType::createType(SoEngine::getClassTypeId(), SbName("CatalogProbeEngine"));
    SoType::createType(SoNode::getClassTypeId(), SbName("CatalogProbeNode"));
  });
  ASSERT_EQ(added.size(), 2u);
  EXPECT_STREQ(added[0].getName().getString(), "CatalogProbeEngine");
  EXPECT_STREQ(added[1].getName().getString(), "CatalogProbeNode");
}

TEST(NodeCatalog, ASecondRegistrationOfTheKitAddsNothing) {
  SoDB::init();
  // Run alone (as ctest runs each test), the first registration adds the kit; in a
  // program that registered it before, nothing.
  const bool knownBefore = SoType::fromName("ClothEngine") != SoType::badType();
  std::vector<std::string> names;
  for (SoType type : typesAddedBy([] { figment::init(); })) names.emplace_back(type.getName().getString());
  if (!knownBefore) {
    for (const char* kit : {"ClothEngine", "ClothingLayer", "DepthSortedGroup", "Mannequin", "StencilSeparator"})
      EXPECT_NE(std::find(names.begin(), names.end(), kit), names.end()) << kit;
  }
  EXPECT_TRUE(typesAddedBy([] { figment::init(); }).empty());
}

TEST(NodeCatalog, DescribesEachFieldWithItsTypeAndDefault) {
  figment::init();
  const std::string text = describeTypes({SoType::fromName("ClothEngine"), SoType::fromName("Mannequin")});
  EXPECT_EQ(text.rfind("ClothEngine (engine, derived from Engine)\n", 0), 0u) << text;
  for (const char* line : {"  windAmplitude        SFDouble     0\n", "  windFrequency        SFDouble     1\n",
                           "  timeStep             SFDouble     0.05\n",
                           "  integrator           SFEnum       IMPLICIT {EULER, SYMPLECTIC, HEUN, IMPLICIT}\n",
                           "  restPoints           MFVec3f      [ ]\n", "  output positions     MFVec3f\n",
                           "Mannequin (node, derived from Group)\n", "  showVolumes          SFBool       FALSE\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line << "\nin\n" << text;
}

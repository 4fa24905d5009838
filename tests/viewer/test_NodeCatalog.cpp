// --list-nodes' catalogue: FIGMENT's types and their fields from Coin's field data.

#include "nodes/Init.h"
#include "viewer/NodeCatalog.h"

#include <Inventor/SoDB.h>

#include <gtest/gtest.h>

#include <string>

using namespace figment::viewer;

TEST(NodeCatalog, FindsTheTypesARegistrationAdds) {
  SoDB::init();
  figment::init();  // already known: a second registration adds nothing
  EXPECT_TRUE(typesAddedBy([] { figment::init(); }).empty());
}

TEST(NodeCatalog, DescribesEachFieldWithItsTypeAndDefault) {
  figment::init();
  const std::string text = describeTypes({SoType::fromName("ClothEngine"), SoType::fromName("Mannequin")});
  EXPECT_EQ(text.rfind("ClothEngine (engine, derived from Engine)\n", 0), 0u) << text;
  for (const char* line : {"  windAmplitude        SFDouble     0\n", "  windFrequency        SFDouble     1\n",
                           "  timeStep             SFDouble     0.00015\n",
                           "  integrator           SFEnum       HEUN {EULER, SYMPLECTIC, HEUN, IMPLICIT}\n",
                           "  restPoints           MFVec3f      [ ]\n", "  output positions     MFVec3f\n",
                           "Mannequin (node, derived from Group)\n", "  showVolumes          SFBool       FALSE\n"})
    EXPECT_NE(text.find(line), std::string::npos) << line << "\nin\n" << text;
}

// figment::init(): Coin initialised, the kit registered, and a second call harmless.
#include <Inventor/SoDB.h>
#include <Inventor/SoType.h>
#include <gtest/gtest.h>

#include "nodes/Init.h"
#include "nodes/NodeTypes.h"

namespace {

TEST(Init, InitialisesCoinAndRegistersEveryListedType) {
  figment::init();  // with no SoDB::init() before it
  EXPECT_TRUE(SoDB::isInitialized());
  for (const figment::NodeType& type : figment::nodeTypes())
    EXPECT_NE(SoType::fromName(type.name), SoType::badType()) << type.name;
}

TEST(Init, ASecondCallRegistersNothingNew) {
  figment::init();
  const int types = SoType::getNumTypes();
  figment::init();
  EXPECT_EQ(SoType::getNumTypes(), types);
}

}  // namespace

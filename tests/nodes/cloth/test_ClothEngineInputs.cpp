// A ClothEngine's fields as the simulation's types: each method field's enum names are
// the scene spelling DrapeMethod's fieldName gives (the bench sets fields by those names),
// and each value maps to its method; parameters carry the method the fields name.
#include <Inventor/SbName.h>
#include <gtest/gtest.h>

#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

// An engine held for the test (engines are reference counted, as nodes are).
struct HeldEngine {
  ClothEngine* engine = new ClothEngine;
  HeldEngine() { engine->ref(); }
  ~HeldEngine() { engine->unref(); }
  ClothEngine* operator->() const { return engine; }
  ClothEngine& operator*() const { return *engine; }
};

// Each value of `field` by its enum name, with the method the fields then name.
template <class Method>
void expectEveryNameMapsBack(SoSFEnum& field, ClothEngine& engine, Method (*methodOf)(const figment::DrapeMethod&)) {
  ASSERT_GT(field.getNumEnums(), 1);
  for (int i = 0; i < field.getNumEnums(); ++i) {
    SbName name;
    field.setValue(field.getEnum(i, name));
    EXPECT_STREQ(figment::fieldName(methodOf(figment::methodFromFields(engine))), name.getString());
  }
}

}  // namespace

TEST(ClothEngineInputs, EveryMethodFieldsNamesAreTheMethodsSpelling) {
  initCoin();
  const HeldEngine engine;
  expectEveryNameMapsBack<figment::Integrator>(engine->integrator, *engine,
                                               [](const figment::DrapeMethod& m) { return m.integrator; });
  expectEveryNameMapsBack<figment::ContactModel>(engine->contactModel, *engine,
                                                 [](const figment::DrapeMethod& m) { return m.contacts; });
  expectEveryNameMapsBack<figment::AccelerationLimiter>(engine->accelerationLimiter, *engine,
                                                        [](const figment::DrapeMethod& m) { return m.limiter; });
}

TEST(ClothEngineInputs, ParametersCarryTheMethodTheFieldsName) {
  initCoin();
  const HeldEngine engine;
  engine->integrator = ClothEngine::IMPLICIT;
  engine->contactModel = ClothEngine::PENALTY;
  engine->timeStep = 0.04;
  engine->maxTime = 2.0;
  const figment::ClothParameters p = figment::parametersFromFields(*engine);
  EXPECT_EQ(figment::DrapeMethod::of(p), figment::methodFromFields(*engine));
  EXPECT_EQ(figment::methodFromFields(*engine).text(), "implicit+penalty:0.04");
  EXPECT_DOUBLE_EQ(p.maxTime, 2.0);
}

// ClothEngine: translates fields into a simulation, lazily, and never lets an error
// escape; findClothEngines finds the engines that feed a scene.

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoVertexProperty.h>
#include <gtest/gtest.h>

#include "nodes/SceneSearch.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/cloth/ClothParameters.h"
#include "sim/cloth/MaterialPresets.h"
#include "support/SceneTestSupport.h"

namespace test_ClothEngine {

using namespace figment::test;

namespace {

// A 10 x 10 grid of cloth 0.5 m wide at 1 m, falling for 0.02 s; `fields` are added to
// the engine's; `restPoints` and `coordIndex`, when given, replace its connections.
std::string clothScene(const std::string& fields, const std::string& restPoints = "",
                       const std::string& coordIndex = "") {
  const Grid g = grid(10, 0.5, 1.0);
  return "#Inventor V2.1 ascii\nSeparator {\n"
         "  Switch { whichChild -1\n"
         "    DEF Rest Coordinate3 { point [ " +
         g.points +
         " ] }\n"
         "    DEF Faces IndexedFaceSet { coordIndex [ " +
         g.coordIndex +
         " ] }\n"
         "  }\n"
         "  DEF Cloth Coordinate3 {\n"
         "    point = DEF Drape ClothEngine {\n"
         "      restPoints " +
         (restPoints.empty() ? "= USE Rest.point" : restPoints) +
         "\n"
         "      coordIndex " +
         (coordIndex.empty() ? "= USE Faces.coordIndex" : coordIndex) +
         "\n"
         "      maxTime 0.02\n" +
         // Written for the paper's explicit path, once the default: named unless a test names its own.
         (fields.find("integrator") == std::string::npos ? "      integrator HEUN\n" : "") + fields +
         "    } . positions\n"
         "  }\n"
         "  ClothingLayer { coordIndex = USE Faces.coordIndex }\n"
         "}\n";
}

class ClothEngineTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }
};

}  // namespace

// The fields' defaults are the simulation's, but the method: backward Euler at 1/20 s, where
// the simulation's defaults are the paper's explicit path, which `integrator HEUN` alone
// gives back (the unwritten timeStep is then the simulation's).
TEST_F(ClothEngineTest, DefaultsAreTheSimulationsDefaultsButTheMethod) {
  ClothEngine* engine = new ClothEngine;
  engine->ref();
  const figment::ClothParameters sim;
  EXPECT_EQ(engine->thickness.getValue(), sim.material.thickness);
  EXPECT_EQ(engine->density.getValue(), sim.material.density);
  EXPECT_EQ(engine->youngsModulus.getValue(), sim.material.youngsModulus);
  EXPECT_EQ(engine->poissonRatio.getValue(), sim.material.poissonRatio);
  EXPECT_EQ(engine->integrator.getValue(), ClothEngine::IMPLICIT);
  EXPECT_EQ(engine->timeStep.getValue(), 0.05);
  EXPECT_EQ(engine->timeStepSeconds(), 0.05);
  EXPECT_EQ(sim.integrator, figment::Integrator::Heun);
  for (int explicitOne : {ClothEngine::HEUN, ClothEngine::EULER, ClothEngine::SYMPLECTIC}) {
    engine->integrator = explicitOne;
    EXPECT_EQ(engine->timeStepSeconds(), sim.timeStep);
  }
  engine->integrator = ClothEngine::IMPLICIT;
  engine->maxTime = 0.01;  // a run shorter than the default step is one step
  EXPECT_EQ(engine->timeStepSeconds(), 0.01);
  engine->maxTime = sim.maxTime;
  engine->timeStep = 0.05;  // written, it is the step whatever the integrator
  engine->integrator = ClothEngine::HEUN;
  EXPECT_EQ(engine->timeStepSeconds(), 0.05);
  EXPECT_EQ(engine->maxTime.getValue(), sim.maxTime);
  EXPECT_EQ(engine->restSpeed.getValue(), sim.rest.speedThreshold);
  EXPECT_EQ(engine->restWindow.getValue(), sim.rest.window);
  EXPECT_FLOAT_EQ(engine->gravity.getValue()[1], float(sim.gravity.y()));
  EXPECT_EQ(engine->airResistance.getValue(), sim.airResistance);
  EXPECT_EQ(engine->friction.getValue(), sim.friction);
  EXPECT_EQ(engine->clearance.getValue(), sim.clearance);
  EXPECT_EQ(engine->strainRateDamping.getValue(), sim.strainRateDamping);
  EXPECT_EQ(engine->windDirection.getValue(),
            SbVec3f(float(sim.wind.direction.x()), float(sim.wind.direction.y()), float(sim.wind.direction.z())));
  EXPECT_EQ(engine->windAmplitude.getValue(), sim.wind.amplitude);
  EXPECT_EQ(engine->windFrequency.getValue(), sim.wind.frequency);
  EXPECT_EQ(engine->windPhaseInterval.getValue(), sim.wind.meanPhaseInterval);
  EXPECT_EQ(uint64_t(engine->windSeed.getValue()), sim.wind.seed);
  EXPECT_EQ(engine->contactModel.getValue(), ClothEngine::CONSTRAINTS);
  EXPECT_EQ(sim.implicitSolver.contacts, figment::ContactModel::Constraints);
  EXPECT_EQ(engine->restPoints.getNum(), 0);
  EXPECT_EQ(engine->coordIndex.getNum(), 0);
  EXPECT_EQ(engine->body.getValue(), nullptr);
  engine->unref();
}

TEST_F(ClothEngineTest, SimulatesOncePerChangeOfItsInputs) {
  SceneRoot root = readString(clothScene(""));
  ASSERT_TRUE(root);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
  ASSERT_NE(engine, nullptr);
  EXPECT_EQ(engine->evaluationCount(), 0) << "reading a scene simulates nothing";

  const SbVec3f first = cloth->point[0];
  const SbVec3f again = cloth->point[0];
  EXPECT_EQ(engine->evaluationCount(), 1);
  EXPECT_EQ(first, again);
  EXPECT_LT(first[1], 1.0f) << "the cloth fell";
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_EQ(engine->lastRun().triangles, 162);
  EXPECT_GT(engine->lastRun().run.iterations, 0);

  // Traversals read the coordinates without simulating again.
  const SbViewportRegion viewport(100, 100);
  SoGetBoundingBoxAction box(viewport);
  box.apply(root.get());
  SoCallbackAction callback;
  callback.apply(root.get());
  box.apply(root.get());
  EXPECT_EQ(engine->evaluationCount(), 1);

  engine->thickness = 0.001;
  EXPECT_EQ(engine->evaluationCount(), 1) << "changing an input only marks the output dirty";
  box.apply(root.get());
  (void)cloth->point[0];
  EXPECT_EQ(engine->evaluationCount(), 2);
}

TEST_F(ClothEngineTest, EqualInputsGiveIdenticalPositions) {
  SceneRoot root = readString(clothScene(""));
  ASSERT_TRUE(root);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
  const std::vector<SbVec3f> first(cloth->point.getValues(0), cloth->point.getValues(0) + cloth->point.getNum());
  engine->maxTime.touch();  // same values, new evaluation
  const std::vector<SbVec3f> second(cloth->point.getValues(0), cloth->point.getValues(0) + cloth->point.getNum());
  EXPECT_EQ(engine->evaluationCount(), 2);
  EXPECT_EQ(first, second);
}

TEST_F(ClothEngineTest, ClothRestsOnTheBodyInsteadOfFallingThrough) {
  TempDir dir;
  dir.file("cube.obj", cubeObj());
  // A 0.6 m square 5 cm above a unit cube's top (y = 1), centred over it.
  const Grid g = grid(10, 0.6, 1.05, 0.5, 0.5);
  const std::string path = dir.file("drape.iv",
                                    "#Inventor V2.1 ascii\nSeparator {\n  DEF Box MeshFile { fileName \"cube.obj\" }\n"
                                    "  DEF Cloth Coordinate3 { point = DEF Drape ClothEngine {\n"
                                    "    restPoints [ " +
                                        g.points + " ] coordIndex [ " + g.coordIndex +
                                        " ]\n"
                                        "    body USE Box  maxTime 0.3 } . positions }\n"
                                        "  IndexedFaceSet { coordIndex [ " +
                                        g.coordIndex + " ] }\n}\n");
  SceneRoot root = readFile(path);
  ASSERT_TRUE(root);
  auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  float lowest = 10.0f;
  for (int i = 0; i < cloth->point.getNum(); ++i) lowest = std::min(lowest, cloth->point[i][1]);
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_GT(lowest, 1.0f) << "no node went into the box";
  EXPECT_LT(lowest, 1.03f) << "the cloth came down onto the box";
}

TEST_F(ClothEngineTest, FacesWithMoreCornersAreFans) {
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nCoordinate3 { point = DEF Drape ClothEngine {\n"
      "  restPoints [ 0 1 0, 1 1 0, 1 1 1, 0.5 1 1.5, 0 1 1 ]  coordIndex [ 0 1 2 3 4 ]  maxTime 0.001\n"
      "} . positions }\n");
  ASSERT_TRUE(root);
  auto* coords = find<SoCoordinate3>(root.get());
  EXPECT_EQ(coords->point.getNum(), 5);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_EQ(engine->lastRun().triangles, 3) << "a pentagon without a final -1 is 3 triangles";
}

TEST_F(ClothEngineTest, WindFieldsReachTheSimulation) {
  // The horizontal sheet falls for 0.02 s, a quarter period of 12.5 Hz: wind blowing up
  // (face-on) slows its fall; wind along the sheet (edge-on) changes nothing.
  auto drape = [](const std::string& fields) {
    SceneRoot root = readString(clothScene(fields));
    EXPECT_TRUE(root);
    auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
    std::vector<SbVec3f> x(cloth->point.getValues(0), cloth->point.getValues(0) + cloth->point.getNum());
    auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
    EXPECT_EQ(engine->lastError(), "");
    return x;
  };
  const std::string gust = "windAmplitude 1 windFrequency 12.5 windPhaseInterval 0 windSeed 4\n";
  const std::vector<SbVec3f> calm = drape("");
  const std::vector<SbVec3f> up = drape(gust + "windDirection 0 2 0\n");
  const std::vector<SbVec3f> along = drape(gust + "windDirection 1 0 0\n");
  EXPECT_GT(up[0][1], calm[0][1] + 1e-4f) << "face-on wind pushed the sheet up";
  EXPECT_EQ(along, calm);
}

// --- bad input: one line naming the engine, the field and the value -----------------

struct BadField {
  std::string fields;                            // added to the engine
  std::string expected;                          // the whole lastError()
  std::string restPoints = {}, coordIndex = {};  // replace the connections when given
  friend void PrintTo(const BadField& bad, std::ostream* out) { *out << bad.expected; }
};

class ClothEngineBadField : public ::testing::TestWithParam<BadField> {
 protected:
  void SetUp() override { initCoin(); }
};

TEST_P(ClothEngineBadField, IsReportedAndTheOutputIsTheRestShape) {
  const BadField& bad = GetParam();
  SceneRoot root = readString(clothScene(bad.fields, bad.restPoints, bad.coordIndex));
  ASSERT_TRUE(root);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  auto* cloth = find<SoCoordinate3>(root.get(), "Cloth");
  CapturedErrors errors;
  const SoMFVec3f& rest = engine->restPoints;
  ASSERT_EQ(cloth->point.getNum(), rest.getNum());
  for (int i = 0; i < rest.getNum(); ++i) ASSERT_EQ(cloth->point[i], rest[i]);
  EXPECT_EQ(engine->lastError(), GetParam().expected);
  EXPECT_NE(errors.all().find(GetParam().expected), std::string::npos) << "posted through SoDebugError";
  EXPECT_EQ(engine->lastError().find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Fields, ClothEngineBadField,
    ::testing::Values(
        BadField{"thickness -0.001", "ClothEngine 'Drape': thickness = -0.001 must be > 0"},
        BadField{"density 0", "ClothEngine 'Drape': density = 0 must be > 0"},
        BadField{"youngsModulus -5", "ClothEngine 'Drape': youngsModulus = -5 must be > 0"},
        BadField{"poissonRatio 0.5", "ClothEngine 'Drape': poissonRatio = 0.5 must be in (-1, 0.5)"},
        BadField{"poissonRatio -1", "ClothEngine 'Drape': poissonRatio = -1 must be in (-1, 0.5)"},
        BadField{"timeStep 0", "ClothEngine 'Drape': timeStep = 0 must be > 0"},
        BadField{"timeStep 1e-30",
                 "ClothEngine 'Drape': timeStep = 1e-30 would take 2e+28 steps to maxTime = 0.02, more than 1e+07"},
        BadField{"material \"tweed\"",
                 "ClothEngine 'Drape': material = \"tweed\" is not a preset (cotton, silk, denim, jersey)"},
        BadField{"strainLimit -0.1", "ClothEngine 'Drape': strainLimit = -0.1 must be >= 0"},
        BadField{"accelerationLimiter CLAMP accelerationLimit 0",
                 "ClothEngine 'Drape': accelerationLimit = 0 must be > 0"},
        BadField{"windAmplitude -0.1", "ClothEngine 'Drape': windAmplitude = -0.1 must be >= 0"},
        BadField{"windFrequency -1", "ClothEngine 'Drape': windFrequency = -1 must be >= 0"},
        BadField{"windPhaseInterval -0.5", "ClothEngine 'Drape': windPhaseInterval = -0.5 must be >= 0"},
        BadField{"windSeed -3", "ClothEngine 'Drape': windSeed = -3 must be >= 0"},
        BadField{"integrator HEUN contactModel PENALTY",
                 "ClothEngine 'Drape': contactModel PENALTY needs integrator IMPLICIT"},
        BadField{"", "ClothEngine 'Drape': coordIndex[2] = 100 is not a vertex: restPoints has 100 points", "",
                 "[ 0 1 100 -1 ]"},
        BadField{"", "ClothEngine 'Drape': coordIndex: the face at [0] has 2 corners, fewer than 3", "", "[ 0 1 -1 ]"},
        BadField{"", "ClothEngine 'Drape': restPoints is empty", "[ ]"},
        BadField{"body Cube { }",
                 "ClothEngine 'Drape': body: Cube is not a collision body (use a MeshFile, a Mannequin or a "
                 "CollisionGroup)"},
        BadField{"body MeshFile { }", "ClothEngine 'Drape': body: MeshFile has no mesh"}));

// --- finding the engines of a scene --------------------------------------------------

TEST_F(ClothEngineTest, FindsEachEngineFeedingTheSceneOnceInSceneOrder) {
  SceneRoot root = readString(
      "#Inventor V2.1 ascii\nSeparator {\n"
      "  Coordinate3 { point = DEF A ClothEngine { } . positions }\n"
      "  Switch { whichChild -1  Coordinate3 { point = DEF B ClothEngine { } . positions } }\n"
      "  IndexedFaceSet { vertexProperty VertexProperty { vertex = DEF C ClothEngine { } . positions } }\n"
      "  Coordinate3 { point = USE A . positions }\n"
      "}\n");
  ASSERT_TRUE(root);
  const std::vector<ClothEngine*> engines = figment::findClothEngines(root.get());
  std::vector<std::string> names;
  for (const ClothEngine* e : engines) names.emplace_back(e->getName().getString());
  EXPECT_EQ(names, (std::vector<std::string>{"A", "B", "C"}));
  for (const ClothEngine* e : engines) EXPECT_EQ(e->evaluationCount(), 0) << "finding evaluates nothing";
}

TEST(ClothEngineStability, FieldsReachTheSimulation) {
  // Stiff cloth at a step far too large: without limiters each integrator blows up and
  // says which it was; strain clamping and a clamped acceleration keep the run finite.
  initCoin();
  const std::string tooLarge = "youngsModulus 1e9 strainRateDamping 0 timeStep 0.004 maxTime 0.4\n";
  for (const auto& [field, method] :
       {std::pair{"integrator EULER", "explicit Euler"}, std::pair{"integrator SYMPLECTIC", "symplectic Euler"},
        std::pair{"integrator HEUN", "improved Euler (Heun)"}}) {
    SceneRoot root = readString(clothScene(tooLarge + field + "\n"));
    ASSERT_TRUE(root);
    auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
    CapturedErrors quiet;
    find<SoCoordinate3>(root.get(), "Cloth")->point.getNum();  // evaluates
    EXPECT_NE(engine->lastError().find(std::string("method ") + method), std::string::npos) << engine->lastError();
  }
  SceneRoot root =
      readString(clothScene(tooLarge + "strainLimit 0.05 accelerationLimiter CLAMP accelerationLimit 5\n"));
  ASSERT_TRUE(root);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  find<SoCoordinate3>(root.get(), "Cloth")->point.getNum();
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_GT(engine->lastRun().run.iterations, 0);
}

TEST(ClothEngineMaterial, APresetFillsWhatTheSceneDidNotWrite) {
  initCoin();
  SceneRoot root = readString(clothScene("material \"denim\"  thickness 0.001\n"));
  ASSERT_TRUE(root);
  auto* engine = static_cast<ClothEngine*>(SoBase::getNamedBase("Drape", ClothEngine::getClassTypeId()));
  const figment::Material denim = *figment::materialPreset("denim");
  const figment::Material used = figment::materialFromFields(*engine);
  EXPECT_EQ(used.thickness, 0.001);  // written: overrides the preset
  EXPECT_NE(denim.thickness, 0.001);
  EXPECT_EQ(used.density, denim.density);
  EXPECT_EQ(used.youngsModulus, denim.youngsModulus);
  EXPECT_EQ(used.poissonRatio, denim.poissonRatio);
}

}  // namespace test_ClothEngine

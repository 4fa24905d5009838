// ClothEngine with the drape cache of its context: a second evaluation with the same
// inputs reads the kept drape (bit for bit what the simulation gave, without
// simulating); a damaged entry, or one whose record is of another version, is dropped,
// said and draped again; the key names the node library's file, not the program's, and
// changes with every field of the engine and of the Mannequin it drapes on, one at a time.
#include <Inventor/SoPath.h>
#include <Inventor/fields/SoFields.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/nodes/SoCube.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <memory>

#include "io/DrapeCache.h"
#include "io/DrapeRecord.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/DrapeContext.h"
#include "nodes/cloth/DrapeKey.h"
#include "support/ShippedGarmentScene.h"
#include "support/TempDir.h"

namespace test_DrapeCacheEngine {

using namespace figment::test;

namespace {

// A drape context with a cache in `folder`, handed to `engine`.
class CachingContext {
 public:
  CachingContext(const std::filesystem::path& folder, ClothEngine& engine)
      : cache_(std::make_shared<figment::DrapeCache>(folder, 1u << 26)),
        context_(std::make_shared<figment::DrapeContext>()) {
    context_->cache = cache_;
    engine.setDrapeContext(context_);
  }
  const figment::DrapeCache& cache() const { return *cache_; }

 private:
  std::shared_ptr<figment::DrapeCache> cache_;
  std::shared_ptr<figment::DrapeContext> context_;
};

std::vector<SbVec3f> drape(ClothEngine& engine) {
  SoMFVec3f positions;
  positions.connectFrom(&engine.positions);
  positions.evaluate();
  return {positions.getValues(0), positions.getValues(0) + positions.getNum()};
}

bool sameBits(const std::vector<SbVec3f>& a, const std::vector<SbVec3f>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(SbVec3f)) == 0;
}

// Gives `field` another value of its type; false for a type this does not know.
bool change(SoField& field) {
  const SoType type = field.getTypeId();
  field.disconnect();  // keeps the value it had
  if (type == SoSFFloat::getClassTypeId())
    return static_cast<SoSFFloat&>(field).setValue(static_cast<SoSFFloat&>(field).getValue() * 1.01f + 0.001f), true;
  if (type == SoSFDouble::getClassTypeId())
    return static_cast<SoSFDouble&>(field).setValue(static_cast<SoSFDouble&>(field).getValue() * 1.01 + 0.001), true;
  if (type == SoSFInt32::getClassTypeId())
    return static_cast<SoSFInt32&>(field).setValue(static_cast<SoSFInt32&>(field).getValue() + 1), true;
  if (type == SoSFBool::getClassTypeId())
    return static_cast<SoSFBool&>(field).setValue(!static_cast<SoSFBool&>(field).getValue()), true;
  if (type == SoSFEnum::getClassTypeId()) {
    auto& f = static_cast<SoSFEnum&>(field);
    int value = 0;
    SbName name;
    for (int i = 0; i < f.getNumEnums(); ++i)
      if (f.getEnum(i, name) != f.getValue()) value = f.getEnum(i, name);
    return f.setValue(value), true;
  }
  if (type == SoSFString::getClassTypeId())
    return static_cast<SoSFString&>(field).setValue((static_cast<SoSFString&>(field).getValue() + "x").getString()),
           true;
  if (type == SoSFVec3f::getClassTypeId())
    return static_cast<SoSFVec3f&>(field).setValue(static_cast<SoSFVec3f&>(field).getValue() + SbVec3f(0.001f, 0, 0)),
           true;
  if (type == SoSFColor::getClassTypeId()) return static_cast<SoSFColor&>(field).setValue(0.1f, 0.2f, 0.3f), true;
  if (type == SoSFNode::getClassTypeId()) {
    auto& f = static_cast<SoSFNode&>(field);
    return f.setValue(f.getValue() ? nullptr : new SoCube), true;
  }
  if (type == SoMFVec3f::getClassTypeId()) {
    auto& f = static_cast<SoMFVec3f&>(field);
    return f.set1Value(0, f.getNum() ? f[0] + SbVec3f(0, 1e-6f, 0) : SbVec3f(0, 0, 0)), true;
  }
  if (type == SoMFVec2f::getClassTypeId()) {
    auto& f = static_cast<SoMFVec2f&>(field);
    return f.set1Value(0, f.getNum() ? f[0] + SbVec2f(0, 1e-6f) : SbVec2f(0, 0)), true;
  }
  if (type == SoMFInt32::getClassTypeId()) {
    auto& f = static_cast<SoMFInt32&>(field);
    return f.set1Value(f.getNum(), -1), true;
  }
  if (type == SoMFFloat::getClassTypeId()) {
    auto& f = static_cast<SoMFFloat&>(field);
    return f.set1Value(0, f.getNum() ? f[0] + 0.01f : 1.0f), true;
  }
  if (type == SoMFString::getClassTypeId()) {
    auto& f = static_cast<SoMFString&>(field);
    return f.set1Value(f.getNum(), "x"), true;
  }
  if (type == SoMFRotation::getClassTypeId()) {
    auto& f = static_cast<SoMFRotation&>(field);
    return f.set1Value(0, SbRotation(SbVec3f(0, 1, 0), 0.1f) * (f.getNum() ? f[0] : SbRotation::identity())), true;
  }
  return false;
}

// Every field of `container` changed in turn and put back: each change changes the key,
// and putting the value back gives the scene's own key again.
void expectEveryFieldChangesTheKey(const std::string& what, SoFieldContainer* (*find)(const ShippedGarmentScene&)) {
  const ShippedGarmentScene scene("dress.iv");
  ASSERT_NE(scene.engine(), nullptr);
  SoFieldContainer* container = find(scene);
  ASSERT_NE(container, nullptr);
  const std::string original = figment::drapeKey(*scene.engine(), "");
  SoFieldList fields;
  container->getFields(fields);
  ASSERT_GT(fields.getLength(), 3);
  for (int i = 0; i < fields.getLength(); ++i) {
    SoField& field = *fields[i];
    SbName name;
    container->getFieldName(&field, name);
    std::unique_ptr<SoField> kept(static_cast<SoField*>(field.getTypeId().createInstance()));
    kept->copyFrom(field);
    ASSERT_TRUE(change(field)) << what << "." << name.getString() << ": a field type this test cannot change";
    EXPECT_NE(figment::drapeKey(*scene.engine(), ""), original) << what << "." << name.getString();
    field.copyFrom(*kept);
    EXPECT_EQ(figment::drapeKey(*scene.engine(), ""), original) << what << "." << name.getString() << " put back";
  }
}

SoFieldContainer* engineOf(const ShippedGarmentScene& scene) {
  return scene.engine();
}
SoFieldContainer* mannequinOf(const ShippedGarmentScene& scene) {
  const SoPathList found = figment::findAll(scene.root(), Mannequin::getClassTypeId());
  return found.getLength() == 1 ? found[0]->getTail() : nullptr;
}

}  // namespace

TEST(DrapeCacheEngine, ASecondDrapeIsReadBitForBitWithoutSimulating) {
  const TempDir dir;
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  const CachingContext cache(dir.path(), engine);
  const std::vector<SbVec3f> first = drape(engine);
  ASSERT_EQ(engine.lastError(), "");
  EXPECT_FALSE(engine.lastRun().fromCache);
  const int steps = engine.lastRun().run.iterations;
  engine.restPoints.touch();  // evaluate again, same inputs
  const std::vector<SbVec3f> second = drape(engine);
  EXPECT_TRUE(engine.lastRun().fromCache);
  EXPECT_EQ(engine.lastRun().run.iterations, steps);  // the statistics of the run that made it
  EXPECT_TRUE(sameBits(first, second));
  EXPECT_EQ(engine.lastCacheMessage(), "");
}

TEST(DrapeCacheEngine, ADamagedEntryIsDroppedSaidAndDrapedAgain) {
  const TempDir dir;
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  const CachingContext cache(dir.path(), engine);
  const std::vector<SbVec3f> first = drape(engine);
  const std::filesystem::path entry = cache.cache().entryPath(figment::drapeKey(engine, ""));
  ASSERT_TRUE(std::filesystem::exists(entry));
  {
    std::fstream file(entry, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(1000);
    file.put('\x55');
  }
  engine.restPoints.touch();
  const std::vector<SbVec3f> second = drape(engine);
  EXPECT_FALSE(engine.lastRun().fromCache);
  EXPECT_NE(engine.lastCacheMessage().find(entry.string()), std::string::npos) << engine.lastCacheMessage();
  EXPECT_TRUE(sameBits(first, second));         // simulated again, to the same bits
  EXPECT_TRUE(std::filesystem::exists(entry));  // and kept again
}

TEST(DrapeCacheEngine, ARecordOfAnotherVersionIsDroppedSaidAndMadeAgain) {
  const TempDir dir;
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  const CachingContext cache(dir.path(), engine);
  const std::vector<SbVec3f> first = drape(engine);
  const std::string key = figment::drapeKey(engine, "");
  std::string problem;
  std::optional<std::vector<unsigned char>> entry = cache.cache().find(key, problem);
  ASSERT_TRUE(entry) << problem;
  // A sound entry (its checksum matches) whose record says it is of a later version.
  const std::uint32_t later = figment::kDrapeRecordVersion + 1;
  std::memcpy(entry->data(), &later, sizeof later);  // a record starts with its version
  ASSERT_EQ(cache.cache().store(key, *entry), "");
  engine.restPoints.touch();
  const std::vector<SbVec3f> second = drape(engine);
  EXPECT_FALSE(engine.lastRun().fromCache);
  EXPECT_NE(engine.lastCacheMessage().find(cache.cache().entryPath(key).string()), std::string::npos);
  EXPECT_NE(engine.lastCacheMessage().find("version " + std::to_string(later)), std::string::npos)
      << engine.lastCacheMessage();
  EXPECT_TRUE(sameBits(first, second));
  // Made again in this version: the next evaluation reads it.
  engine.restPoints.touch();
  EXPECT_TRUE(sameBits(first, drape(engine)));
  EXPECT_TRUE(engine.lastRun().fromCache);
  EXPECT_EQ(engine.lastCacheMessage(), "");
}

TEST(DrapeCacheEngine, TheKeyNamesTheNodeLibraryNotTheProgram) {
  const ShippedGarmentScene scene("dress.iv");
  const std::string key = figment::drapeKey(*scene.engine(), "");
  EXPECT_NE(key.find("library=/"), std::string::npos) << key.substr(0, 200);
  EXPECT_NE(key.find("libfigment_nodes.so"), std::string::npos) << key.substr(0, 200);
  EXPECT_EQ(key.find("test_nodes"), std::string::npos) << "the test program is not what drapes";
}

TEST(DrapeCacheEngine, EveryFieldOfTheEngineChangesTheKey) {
  expectEveryFieldChangesTheKey("ClothEngine", engineOf);
}

TEST(DrapeCacheEngine, EveryFieldOfTheMannequinChangesTheKey) {
  expectEveryFieldChangesTheKey("Mannequin", mannequinOf);
}

TEST(DrapeCacheEngine, WithoutACacheEveryEvaluationSimulates) {
  const ShippedGarmentScene scene("dress.iv");
  ClothEngine& engine = *scene.engine();
  drape(engine);
  engine.restPoints.touch();
  drape(engine);
  EXPECT_FALSE(engine.lastRun().fromCache);
  EXPECT_EQ(engine.evaluationCount(), 2);
}

}  // namespace test_DrapeCacheEngine

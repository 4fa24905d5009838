// The default scene end to end: scenes/dress.iv is read, the dress is draped on the
// default body by the simulation and comes to rest outside the body, held up at the
// shoulders, and the front view shows both dress and skin.
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/fields/SoMFVec3f.h>
#include <Inventor/nodes/SoBaseColor.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDrawStyle.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoLightModel.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>
#include <Inventor/nodes/SoTransform.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "guard/SceneFile.h"
#include "headless/InitHeadless.h"
#include "nodes/SceneSearch.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/render/ClothingLayer.h"
#include "session/SceneRenderer.h"
#include "session/SceneStaging.h"
#include "sim/body/Skeleton.h"
#include "sim/collision/MeshCollider.h"
#include "sim/collision/VolumeSetCollider.h"
#include "sim/core/DisplaySubdivision.h"
#include "sim/drape/DrapeReport.h"
#include "support/Pixels.h"
#include "support/RenderedImage.h"

using namespace figment::session;

namespace {

// One drape for the whole suite: it is the slow part (seconds).
class DefaultScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    figment::initHeadless();
    std::string error;
    scene_ = figment::guard::readScene(std::string(FIGMENT_SOURCE_DIR) + "/scenes/dress.iv", error);
    ASSERT_NE(scene_, nullptr) << error;
    scene_->ref();
    engines_ = figment::findClothEngines(scene_);
    ASSERT_EQ(engines_.size(), 1u);
    staged_ = stageScene(scene_, {400, 300}, ViewDirection{0.0, 0.0});  // evaluates the engine
    staged_->ref();
  }
  static void TearDownTestSuite() {
    if (staged_) staged_->unref();
    if (scene_) scene_->unref();
    staged_ = scene_ = nullptr;
  }
  static MeshFile* node(const char* name) { return dynamic_cast<MeshFile*>(SoNode::getByName(name)); }
  // The garment's coordinates as the renderer sees them: the Coordinate3 the engine feeds.
  static std::vector<figment::Vec3> drapedPositions() {
    SoSearchAction search;
    search.setType(SoCoordinate3::getClassTypeId());
    search.setInterest(SoSearchAction::ALL);
    search.apply(scene_);
    for (int p = 0; p < search.getPaths().getLength(); ++p) {
      auto* coordinates = static_cast<SoCoordinate3*>(search.getPaths()[p]->getTail());
      SoEngineOutput* source = nullptr;
      if (!coordinates->point.getConnectedEngine(source) || source != &engines_.front()->positions) continue;
      std::vector<figment::Vec3> out;
      for (int i = 0; i < coordinates->point.getNum(); ++i)
        out.emplace_back(coordinates->point[i][0], coordinates->point[i][1], coordinates->point[i][2]);
      return out;
    }
    ADD_FAILURE() << "no Coordinate3 fed by the dress's ClothEngine";
    return {};
  }

  // Inserts `child` before the named node in its parent (or as the first child of the
  // named group with `inside`); returns an undo.
  static std::function<void()> insert(const char* name, SoNode* child, bool inside = false) {
    SoSearchAction search;
    search.setName(name);
    search.apply(scene_);
    SoPath* path = search.getPath();
    if (!path) {
      ADD_FAILURE() << "no node " << name;
      return [] {};
    }
    auto* parent = static_cast<SoGroup*>(inside ? path->getTail() : path->getNodeFromTail(1));
    parent->insertChild(child, inside ? 0 : parent->findChild(path->getTail()));
    return [parent, child] { parent->removeChild(child); };
  }
  // Renders the scene from `azimuth` in flat colours: torso red, arms green, dress blue;
  // with `plain` the dress is an IndexedFaceSet (the depth buffer alone). With
  // `outsideOnly`, only the dress, as a solid whose back faces are culled: the pixels
  // where its outside faces the viewer (not its inside, seen through the neckline).
  // Every variant of one view is framed on the box of the scene as the hybrid nodes draw
  // it: a camera moved by a hair moves the outline by a pixel, which then reads as skin
  // at the rim. (Before the layer's box held its display mesh, the stand-in's box stood
  // up to 2 mm outside the layer's.)
  static figment::test::Image flatRender(double azimuth, bool outsideOnly, bool plain, float shrink = 1.0f) {
    const ImageSize size{300, 400};
    std::vector<std::function<void()>> undo;
    auto colour = [](float r, float g, float b) {
      auto* c = new SoBaseColor;
      c->rgb.setValue(r, g, b);
      return c;
    };
    auto* flat = new SoLightModel;
    flat->model = SoLightModel::BASE_COLOR;
    scene_->insertChild(flat, 0);
    undo.push_back([flat] { scene_->removeChild(flat); });
    undo.push_back(insert("Torso", colour(1, 0, 0)));
    undo.push_back(insert("LeftArm", colour(0, 1, 0), true));
    undo.push_back(insert("RightArm", colour(0, 1, 0), true));
    undo.push_back(insert("Dress", colour(0, 0, 1)));
    if (shrink != 1.0f) {
      // Drawn narrower about the torso's vertical axis: into the skin.
      auto* narrower = new SoTransform;
      narrower->scaleFactor.setValue(shrink, 1.0f, shrink);
      narrower->center.setValue(torsoAxis());
      undo.push_back(insert("Dress", narrower));
    }
    const SbBox3f box = sceneBox(scene_, size);
    if (outsideOnly) {
      auto* invisible = new SoDrawStyle;
      invisible->style = SoDrawStyle::INVISIBLE;
      undo.push_back(insert("Torso", invisible));
      auto* solid = new SoShapeHints;
      solid->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
      solid->shapeType = SoShapeHints::SOLID;
      undo.push_back(insert("Dress", solid));
      plain = true;  // Coin culls an IndexedFaceSet's back faces
    }
    SoSearchAction search;
    search.setName("Dress");
    search.apply(scene_);
    auto* layer = static_cast<ClothingLayer*>(search.getPath()->getTail());
    auto* parent = static_cast<SoGroup*>(search.getPath()->getNodeFromTail(1));
    if (plain) {
      SoNode* faces = plainDress(*layer);
      layer->ref();
      parent->replaceChild(layer, faces);
      undo.push_back([parent, faces, layer] {
        parent->replaceChild(faces, layer);
        layer->unref();
      });
    }
    SoSeparator* root = stageScene(scene_, size, ViewDirection{azimuth, 10.0}, box);
    root->ref();
    figment::test::Image image = figment::test::renderedImage(root, size);
    root->unref();
    for (auto it = undo.rbegin(); it != undo.rend(); ++it) (*it)();
    return image;
  }

  // The dress as the layer draws it, as a plain IndexedFaceSet: its faces, or with a display
  // mesh (displaySubdivision) that mesh's triangles on coordinates of their own.
  static SoNode* plainDress(const ClothingLayer& layer) {
    auto* faces = new SoIndexedFaceSet;
    faces->coordIndex.setNum(0);  // its default is one corner, 0
    const int levels = layer.displaySubdivision.getValue();
    if (levels == 0) {
      faces->coordIndex.connectFrom(const_cast<SoMFInt32*>(&layer.coordIndex));
      return faces;
    }
    const std::vector<figment::Vec3> draped = drapedPositions();
    std::vector<figment::Triangle> triangles;
    for (int i = 0; i + 3 < layer.coordIndex.getNum(); i += 4)
      triangles.push_back({layer.coordIndex[i], layer.coordIndex[i + 1], layer.coordIndex[i + 2]});
    const figment::DisplaySubdivision display(triangles, draped, levels);
    std::vector<figment::Vec3> points, normals;
    display.apply(draped, points, normals);
    auto* group = new SoGroup;
    auto* coordinates = new SoCoordinate3;
    for (size_t i = 0; i < points.size(); ++i)
      coordinates->point.set1Value(int(i), float(points[i].x()), float(points[i].y()), float(points[i].z()));
    for (const figment::Triangle& t : display.triangles())
      for (int v : {t[0], t[1], t[2], -1}) faces->coordIndex.set1Value(faces->coordIndex.getNum(), v);
    group->addChild(coordinates);
    group->addChild(faces);
    return group;
  }

  // The checks of NoSkinInsideTheDressAndArmsInFrontKeepTheirPixels at the dress's
  // displaySubdivision as it is set, from 8 azimuths (as test_HybridNeverHidesCloth), on
  // every pixel where the dress's outside faces the viewer: its outline, the rim seen
  // edge-on, included.
  static void expectNoSkinInsideTheDress() {
    for (double azimuth : {0.0, 45.0, 60.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0}) {
      for (float shrink : {1.0f, 0.93f}) {
        const std::vector<bool> dress = flatRender(azimuth, true, false, shrink).where(figment::test::kBlue);
        const long dressPixels = std::count(dress.begin(), dress.end(), true);
        ASSERT_GT(dressPixels, 5000) << "azimuth " << azimuth << ": the dress's outside faces the viewer";
        const figment::test::Image hybrid = flatRender(azimuth, false, false, shrink);
        const figment::test::Image plain = flatRender(azimuth, false, true, shrink);
        EXPECT_EQ(hybrid.countWithin(figment::test::kRed, dress), 0) << "azimuth " << azimuth << ", shrink " << shrink;
        if (shrink < 1.0f) {
          EXPECT_GT(plain.countWithin(figment::test::kRed, dress), 500) << "azimuth " << azimuth << ": the control";
          continue;  // the arms are judged on the drape as it is
        }
        EXPECT_GE(hybrid.countWithin(figment::test::kGreen, dress), plain.countWithin(figment::test::kGreen, dress))
            << "azimuth " << azimuth;
        if (azimuth == 60.0 || azimuth == 90.0 || azimuth == 270.0) {
          EXPECT_GT(plain.countWithin(figment::test::kGreen, dress), 100) << "the near arm is in front";
        }
      }
    }
  }

  // The dress's vertical axis: the mean of its draped points in x and z.
  static SbVec3f torsoAxis() {
    figment::Vec3 sum = figment::Vec3::Zero();
    const std::vector<figment::Vec3> points = drapedPositions();
    for (const figment::Vec3& p : points) sum += p;
    sum /= double(std::max<size_t>(points.size(), 1));
    return SbVec3f(float(sum.x()), 0.0f, float(sum.z()));
  }

  static SoSeparator* scene_;
  static SoSeparator* staged_;
  static std::vector<ClothEngine*> engines_;
};
SoSeparator* DefaultScene::scene_ = nullptr;
SoSeparator* DefaultScene::staged_ = nullptr;
std::vector<ClothEngine*> DefaultScene::engines_;

}  // namespace

TEST_F(DefaultScene, DressComesToRestWithoutError) {
  const ClothEngine* engine = engines_.front();
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_EQ(engine->evaluationCount(), 1);
  const figment::DrapeReport& run = engine->lastRun();
  EXPECT_TRUE(run.run.atRest) << "simulated " << run.run.simulatedTime << " s";
  EXPECT_GT(run.triangles, 1300);
  EXPECT_LT(run.triangles, 1700);
  EXPECT_LT(run.run.simulatedTime, engine->maxTime.getValue());
}

TEST_F(DefaultScene, NoGarmentVertexInsideTheBody) {
  const MeshFile* body = node("Body");
  ASSERT_NE(body, nullptr);
  const auto collider = body->collider();
  ASSERT_NE(collider, nullptr);
  const double inf = std::numeric_limits<double>::infinity();
  int inside = 0;
  double deepest = 0.0;
  for (const figment::Vec3& p : drapedPositions()) {
    figment::Contact contact;
    collider->contact(p, 0.0, inf, contact);
    if (contact.distance < 0.0) ++inside;
    deepest = std::min(deepest, contact.distance);
  }
  EXPECT_EQ(inside, 0) << "deepest " << deepest * 1000 << " mm inside";
}

TEST_F(DefaultScene, NoGarmentVertexInsideAnyCollisionVolume) {
  // The dress collides with the mannequin's fitted volumes; it ends outside each one.
  const auto* model = dynamic_cast<Mannequin*>(SoNode::getByName("Model"));
  ASSERT_NE(model, nullptr);
  const auto volumes = std::dynamic_pointer_cast<const figment::VolumeSetCollider>(model->collider());
  ASSERT_NE(volumes, nullptr);
  ASSERT_GE(volumes->size(), model->skeleton().parts.size()) << "a volume per part at least";
  int inside = 0;
  for (const figment::Vec3& p : drapedPositions())
    for (size_t i = 0; i < volumes->size(); ++i)
      if (volumes->worldVolume(i).contains(p)) ++inside;
  EXPECT_EQ(inside, 0);
}

TEST_F(DefaultScene, ShouldersHoldTheDressUp) {
  // Where the body holds a strap dress: the top of the shoulders (beside the neck,
  // inside the arms), from the body's own surface.
  const MeshFile* body = node("Body");
  ASSERT_NE(body, nullptr);
  double shoulderTop = -std::numeric_limits<double>::infinity();
  for (const figment::Vec3& v : body->collisionSurface().vertices)
    if (std::abs(v.x()) > 0.08 && std::abs(v.x()) < 0.20 && v.y() < 1.45) shoulderTop = std::max(shoulderTop, v.y());
  double dressTop = -std::numeric_limits<double>::infinity();
  for (const figment::Vec3& p : drapedPositions()) dressTop = std::max(dressTop, p.y());
  // Resting on them, the straps' top lies above the shoulders' (3.1 mm: the radial
  // volume stands 1.7 mm off the skin there, the strap 1.4 mm over it) and no more than
  // the engine's clearance (6 mm) and 2 mm for the volumes' stand-off above: a dress that
  // sags 1 mm below the shoulder or floats 1 cm above it fails (before, 10 cm passed).
  const double gap = dressTop - shoulderTop, clearance = engines_.front()->clearance.getValue();
  RecordProperty("dress_top_above_shoulder_mm", std::to_string(gap * 1000));
  EXPECT_GT(gap, 0.0) << "the dress slid off the shoulders: its top " << -gap * 1000 << " mm below theirs";
  EXPECT_LT(gap, clearance + 0.002) << "the dress floats " << gap * 1000 << " mm above the shoulders";
}

TEST_F(DefaultScene, FrontViewShowsDressAndSkin) {
  SceneRenderer renderer({400, 300});
  ASSERT_EQ(renderer.render(staged_), "");
  const unsigned char* rgb = renderer.pixels();
  int dress = 0, skin = 0;
  const int pixels = 400 * 300;
  for (int i = 0; i < pixels; ++i) {
    const int r = rgb[3 * i], g = rgb[3 * i + 1], b = rgb[3 * i + 2];
    if (b > r + 30 && b > g + 15)
      ++dress;  // the blue dress, lit or in shade
    else if (r > b + 25 && r >= g)
      ++skin;  // the orange-brown skin
  }
  // The dress covers the torso and thighs; skin shows at the head, arms and legs.
  EXPECT_GT(dress, pixels / 50) << "dress pixels " << dress;
  EXPECT_GT(skin, pixels / 50) << "skin pixels " << skin;
  EXPECT_GT(dress, skin / 4) << "dress " << dress << " skin " << skin;
  EXPECT_GT(skin, dress / 4) << "dress " << dress << " skin " << skin;
}

TEST_F(DefaultScene, NoSkinInsideTheDressAndArmsInFrontKeepTheirPixels) {
  // From 8 azimuths (and 60 degrees, the near arm in front of the dress). Wherever the
  // dress's outside faces the viewer, its outline and the rim seen edge-on included, no
  // torso pixel shows, and the arms keep at least the pixels the depth buffer gives them
  // there (from 135 and 225 degrees, 4 and 5 pixels of the near hand in front of the hem,
  // which the dress was drawn over while the stencil rule judged the garment's depth by
  // its bounding box's nearest corner; issue 29). The draped dress stands off the skin by
  // its clearance, so the depth buffer alone shows no torso either (but for a pixel or
  // two at the rim); the control draws it 7 % narrower about its axis (into the skin by
  // up to a centimetre): then the depth buffer alone shows the torso through it (650 to
  // 2,300 pixels a view) and the hybrid nodes still none. At every level of display mesh
  // the scenes draw (0: the paper's drawing of the simulation's faces; 1, the scene's;
  // 2). Before, the hybrid render and its references were framed each on its own scene's
  // box, and the IndexedFaceSet standing in for the display mesh was up to 2 mm larger
  // than the layer's box was then: the outlines moved by a pixel, and 2 to 4 pixels of the rim
  // (up to 11 narrowed) read as skin through the display mesh, none on one camera.
  SoSearchAction search;
  search.setName("Dress");
  search.apply(scene_);
  auto* layer = static_cast<ClothingLayer*>(search.getPath()->getTail());
  const int sceneLevels = layer->displaySubdivision.getValue();
  ASSERT_EQ(sceneLevels, 1) << "scenes/dress.iv draws one level of display mesh";
  for (int levels : {0, sceneLevels, sceneLevels + 1}) {
    layer->displaySubdivision = levels;
    SCOPED_TRACE("displaySubdivision " + std::to_string(levels));
    expectNoSkinInsideTheDress();
  }
  layer->displaySubdivision = sceneLevels;
}

TEST_F(DefaultScene, TheDressIsBoundedAsDrawn) {
  // The layer's bounding box holds the display mesh it draws, which stands up to 2 mm
  // past its faces: the dress bounds as that mesh as an IndexedFaceSet does, at every
  // level; at level 0 the box is the faces' own.
  SoSearchAction search;
  search.setName("Dress");
  search.apply(scene_);
  auto* layer = static_cast<ClothingLayer*>(search.getPath()->getTail());
  auto* parent = static_cast<SoGroup*>(search.getPath()->getNodeFromTail(1));
  auto boxOf = [parent] {
    SoGetBoundingBoxAction bounds(SbViewportRegion(300, 400));
    bounds.apply(parent);
    return bounds.getBoundingBox();
  };
  const int sceneLevels = layer->displaySubdivision.getValue();
  SbBox3f faces;
  for (int levels : {0, 1, 2}) {
    layer->displaySubdivision = levels;
    SCOPED_TRACE("displaySubdivision " + std::to_string(levels));
    const SbBox3f drawn = boxOf();
    if (levels == 0) faces = drawn;
    SoNode* standIn = plainDress(*layer);
    layer->ref();
    parent->replaceChild(layer, standIn);
    const SbBox3f expected = boxOf();
    parent->replaceChild(standIn, layer);
    layer->unref();
    float past = 0.0f;  // how far the box reaches past the faces' box
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(drawn.getMin()[axis], expected.getMin()[axis], 1e-6f) << "axis " << axis;
      EXPECT_NEAR(drawn.getMax()[axis], expected.getMax()[axis], 1e-6f) << "axis " << axis;
      past = std::max({past, faces.getMin()[axis] - drawn.getMin()[axis], drawn.getMax()[axis] - faces.getMax()[axis]});
    }
    if (levels > 0) {
      EXPECT_GT(past, 0.0005f) << "the display mesh stands past the faces";
    }
    RecordProperty("box_past_faces_mm_level_" + std::to_string(levels), std::to_string(past * 1000));
  }
  layer->displaySubdivision = sceneLevels;
}

namespace {
// The worst |strain| of the engine's draped edges against its rest shape.
double worstEdgeStrain(ClothEngine& engine) {
  SoMFVec3f draped;
  draped.connectFrom(&engine.positions);
  double worst = 0.0;
  const int32_t* index = engine.coordIndex.getValues(0);
  for (int i = 0; i + 3 < engine.coordIndex.getNum(); i += 4)
    for (int k = 0; k < 3; ++k) {
      const int a = index[i + k], b = index[i + (k + 1) % 3];
      const double rest = (engine.restPoints[a] - engine.restPoints[b]).length();
      const double now = (draped[a] - draped[b]).length();
      worst = std::max(worst, std::abs(now / rest - 1.0));
    }
  return worst;
}

// Drapes scenes/dress.iv after `adjust` changed its engine; returns the worst edge strain.
double drapeDefaultDress(const std::function<void(ClothEngine&)>& adjust) {
  figment::initHeadless();
  std::string error;
  SoSeparator* scene = figment::guard::readScene(std::string(FIGMENT_SOURCE_DIR) + "/scenes/dress.iv", error);
  EXPECT_NE(scene, nullptr) << error;
  if (!scene) return INFINITY;
  scene->ref();
  const std::vector<ClothEngine*> engines = figment::findClothEngines(scene);
  EXPECT_EQ(engines.size(), 1u);
  ClothEngine* engine = engines.front();
  adjust(*engine);
  engine->positions[0]->evaluate();
  EXPECT_EQ(engine->lastError(), "");
  EXPECT_TRUE(engine->lastRun().run.atRest);
  const double worst = worstEdgeStrain(*engine);
  scene->unref();
  return worst;
}
}  // namespace

TEST(DefaultSceneAtDefaultClearance, ComesToRestWithoutTearing) {
  // The bug this guards: with the acceleration cap at 10 g and the ClothEngine's
  // default clearance (3 mm), the dress fell 3 mm further before the straps caught it,
  // the cap held back the nodes that had to stop it, and the dress stretched to 180 %.
  const double worst = drapeDefaultDress([](ClothEngine& engine) { engine.clearance = 0.003; });
  EXPECT_LT(worst, 0.10) << "an edge stretched by " << worst * 100 << " %";
}

TEST(DefaultSceneImplicit, ComesToRestWithNoStrapHeldStretched) {
  // The bug this guards: the implicit step's static friction was judged on each node's
  // bare mass while the solve's tangential velocity was damped by the step's stiffness,
  // so strap nodes on the shoulders pulled by stretched neighbours read as slow and
  // stuck: the dress rested with strap edges stretched by 70 % (the explicit path: 4 %).
  const double worst = drapeDefaultDress([](ClothEngine& engine) {
    engine.integrator = ClothEngine::IMPLICIT;
    engine.timeStep = 0.01;
  });
  EXPECT_LT(worst, 0.10) << "an edge stretched by " << worst * 100 << " %";
}

#include "serve/scene/OutfitScene.h"

#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoDirectionalLight.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoMaterialBinding.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoShapeHints.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <vector>

#include "io/GarmentCatalogue.h"
#include "nodes/MeshFields.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/HumanBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MannequinSkin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/GarmentSurface.h"
#include "nodes/render/ClothingLayer.h"
#include "serve/request/MeasuredPoses.h"
#include "serve/scene/Wardrobe.h"
#include "sim/collision/MeshCollider.h"
#include "sim/fit/FitMap.h"
#include "sim/fit/SizeFitter.h"
#include "sim/garment/GarmentStyle.h"
#include "sim/pattern/Sewing.h"

namespace figment::serve {

namespace {

SbColor colourOf(const std::string& hex) {
  const long value = std::strtol(hex.c_str(), nullptr, 16);
  return SbColor(float((value >> 16) & 0xff) / 255.f, float((value >> 8) & 0xff) / 255.f, float(value & 0xff) / 255.f);
}

SoMaterial* material(const SbColor& diffuse, float specular, float shininess) {
  auto* node = new SoMaterial;
  node->diffuseColor = diffuse;
  node->specularColor = SbColor(specular, specular, specular + (shininess > 0.25f ? 0.05f : 0.f));
  node->shininess = shininess;
  return node;
}

SoShapeHints* hints(bool solid) {
  auto* node = new SoShapeHints;
  node->vertexOrdering = SoShapeHints::COUNTERCLOCKWISE;
  node->shapeType = solid ? SoShapeHints::SOLID : SoShapeHints::UNKNOWN_SHAPE_TYPE;
  node->creaseAngle = 1.0f;
  return node;
}

void addLights(SoSeparator* root, const LightPreset& preset) {
  for (const LightPreset::Light& light : preset.lights) {
    auto* node = new SoDirectionalLight;
    node->direction = SbVec3f(float(light.direction[0]), float(light.direction[1]), float(light.direction[2]));
    node->intensity = float(light.intensity);
    node->color = SbColor(float(light.colour[0]), float(light.colour[1]), float(light.colour[2]));
    root->addChild(node);
  }
}

Mannequin* mannequin(const RenderRequest& request, const Wardrobe& wardrobe) {
  auto* model = new Mannequin;
  model->body = wardrobe.body();
  const Pose& pose = *ShopperChoices::pose(request.pose);
  for (size_t i = 0; i < pose.joints.size(); ++i) {
    const auto& r = pose.rotations[i];
    model->rotatedJoints.set1Value(int(i), pose.joints[i].c_str());
    model->rotations.set1Value(int(i), SbRotation(SbVec3f(float(r[0]), float(r[1]), float(r[2])), float(r[3])));
  }
  const BodyFactors factors = ShopperChoices::bodyFactors(request.body);
  model->height = float(factors.height);
  model->chest = float(factors.chest);
  model->waist = float(factors.waist);
  model->hips = float(factors.hips);
  model->addChild(wardrobe.volumes());
  return model;
}

// The pattern's rest shape on this body. The paper's patterns come in one size, made for
// the scanned body; a pattern follows the body's stature as the Mannequin's height scales
// the body (uniformly about `origin`, so straps stay on the shoulders: a dress made for
// 1.66 m tangled on a 1.82 m body).
void restShape(ClothEngine* engine, const MeshFile* pattern, const SbVec3f& origin, double height) {
  const int n = pattern->point.getNum();
  const SbVec3f* points = pattern->point.getValues(0);
  std::vector<SbVec3f> shape(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) shape[size_t(i)] = origin + float(height) * (points[i] - origin);
  engine->restPoints.setValues(0, n, shape.data());
}

// Cotton jersey as the shipped scenes drape it: backward Euler at 1/20 s.
ClothEngine* engineFor(const GarmentStyle& style, bool layered, SoNode* body) {
  auto* engine = new ClothEngine;
  engine->body = body;
  engine->thickness = 0.0006;
  engine->density = 300;
  engine->youngsModulus = 1e6;
  engine->poissonRatio = 0.3;
  engine->integrator.set("IMPLICIT");
  if (layered || style.penaltyContacts) engine->contactModel.set("PENALTY");
  engine->timeStep = 0.05;
  engine->maxTimeStep = figment::ImplicitSolverParameters::kShippedMaxTimeStep;
  engine->maxTime = style.maxTime;
  engine->restSpeed = 0.01;
  engine->restWindow = 0.25;
  engine->friction = 0.5;
  engine->clearance = 0.006;
  return engine;
}

struct Draped {
  std::function<void(SoMFVec3f&)> follow;  // connects a field to where the garment lies
  const SoMFInt32* coordIndex;             // the garment's triangles
};

// Follows an engine's drape, or a drape's fixed points.
std::function<void(SoMFVec3f&)> following(ClothEngine* engine) {
  return [engine](SoMFVec3f& field) { field.connectFrom(&engine->positions); };
}
std::function<void(SoMFVec3f&)> following(SoMFVec3f* points) {
  return [points](SoMFVec3f& field) { field.connectFrom(points); };
}

// What the next garment out collides with: the mannequin and every garment beneath.
SoNode* bodyUnder(SoNode* model, const std::vector<Draped>& beneath) {
  if (beneath.empty()) return model;
  auto* group = new CollisionGroup;
  group->body = model;
  for (size_t i = 0; i < beneath.size(); ++i) {
    auto* surface = new GarmentSurface;
    beneath[i].follow(surface->point);
    surface->coordIndex.connectFrom(const_cast<SoMFInt32*>(beneath[i].coordIndex));
    surface->thickness = 0.002f;
    group->layers.set1Value(int(i), surface);
  }
  return group;
}

// Where a garment's fit map goes (null: none) and what it is measured against.
struct FitMapTarget {
  std::vector<OutfitScene::FitMapGarment>* garments = nullptr;
  std::string fabric;  // whose limits colour it
  std::string kind;
  const MeshFile* skin = nullptr;  // a measured body
  ClothParameters parameters;
  std::optional<RestShape> flat;  // a sewn garment's rest shape (else its rest mesh's)
};

// The garment at `coordinates` in its colour, drawn by a ClothingLayer; or with a fit map an
// IndexedFaceSet coloured per vertex once draped (a ClothingLayer draws one material).
// `triangles` fills the drawing node's coordIndex (connects it, or sets it), which `*drawn`
// is then; `rest`: the garment as cut, for its fit map.
SoSeparator* garment(const OutfitItem& item, SoCoordinate3* coordinates,
                     const std::function<void(SoMFInt32&)>& triangles, const FitMapTarget& fitMap,
                     const std::function<TriangleMesh()>& rest, const SoMFInt32** drawn) {
  auto* separator = new SoSeparator;
  SoMaterial* colour = material(colourOf(item.colour), 0.15f, 0.3f);
  separator->addChild(colour);
  separator->addChild(hints(false));  // cloth is seen from both sides
  separator->addChild(coordinates);
  if (fitMap.garments) {
    TriangleMesh cut = rest();
    // One colour a point from the start (the session checks the shapes before they are
    // painted): the garment's own until paintFitMaps.
    const std::vector<SbColor> plain(cut.vertices.size(), colourOf(item.colour));
    colour->diffuseColor.setValues(0, int(plain.size()), plain.data());
    auto* binding = new SoMaterialBinding;
    binding->value = SoMaterialBinding::PER_VERTEX_INDEXED;
    separator->addChild(binding);
    auto* faces = new SoIndexedFaceSet;
    triangles(faces->coordIndex);
    separator->addChild(faces);
    fitMap.garments->push_back(
        {std::move(cut), fitMap.flat, coordinates, colour, fitMap.fabric, fitMap.kind, fitMap.skin, fitMap.parameters});
    *drawn = &faces->coordIndex;
    return separator;
  }
  auto* layer = new ClothingLayer;
  triangles(layer->coordIndex);
  // Drawn smooth (issue 29), as the shipped scenes are: hems read as curves at the drape's
  // cost. The ETag follows, since the build digest covers this program.
  layer->displaySubdivision = OutfitScene::kDisplaySubdivision;
  separator->addChild(layer);
  *drawn = &layer->coordIndex;
  return separator;
}

// Connects a drawing node's coordIndex to `source`.
std::function<void(SoMFInt32&)> connectedTo(const SoMFInt32& source) {
  return [&source](SoMFInt32& field) { field.connectFrom(const_cast<SoMFInt32*>(&source)); };
}

// Coordinates that follow an engine's drape.
SoCoordinate3* coordinatesOf(ClothEngine* engine) {
  auto* coordinates = new SoCoordinate3;
  coordinates->point.connectFrom(&engine->positions);
  return coordinates;
}

// A garment as cut: the engine's rest points and its faces fan-triangulated.
TriangleMesh restMesh(const ClothEngine& engine) {
  TriangleMesh rest;
  for (int i = 0; i < engine.restPoints.getNum(); ++i) {
    const SbVec3f& p = engine.restPoints[i];
    rest.vertices.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<int> face;
  for (int i = 0; i <= engine.coordIndex.getNum(); ++i) {
    const int v = i < engine.coordIndex.getNum() ? engine.coordIndex[i] : -1;
    if (v >= 0) {
      face.push_back(v);
      continue;
    }
    for (size_t k = 2; k < face.size(); ++k) rest.triangles.push_back({face[0], face[k - 1], face[k]});
    face.clear();
  }
  return rest;
}

// The size advice's drape (sim/fit/SizeFitter.h: sizeDrapeParameters) as a ClothEngine's.
// A cut garment over another takes penalty contacts, as scenes/outfit-layers.iv does; a sewn
// one keeps the constraints, its panels sewn shut over the layer beneath (penalty contacts
// let a circle skirt's waistband, pulled shut over a T-shirt, tear: an edge at 1.6 times its
// rest length, against 1.3 with constraints).
ClothEngine* gradedEngine(const std::string& fabric, const ClothParameters& p, bool layered, bool sewn, SoNode* body) {
  auto* engine = new ClothEngine;
  engine->body = body;
  engine->material = fabric.c_str();
  engine->integrator.set("IMPLICIT");
  if (layered && !sewn) engine->contactModel.set("PENALTY");
  engine->timeStep = p.timeStep;
  engine->maxTimeStep = p.implicitSolver.maxTimeStep;
  engine->maxTime = p.maxTime;
  engine->restSpeed = p.rest.speedThreshold;
  engine->restWindow = p.rest.window;
  engine->friction = p.friction;
  engine->clearance = p.clearance;
  return engine;
}

std::vector<SbVec3f> pointsOf(const std::vector<Vec3>& vertices) {
  std::vector<SbVec3f> points;
  for (const Vec3& v : vertices) points.emplace_back(float(v.x()), float(v.y()), float(v.z()));
  return points;
}

void setTriangles(SoMFInt32& coordIndex, const TriangleMesh& mesh) {
  std::vector<int32_t> index;
  for (const auto& t : mesh.triangles) index.insert(index.end(), {int32_t(t[0]), int32_t(t[1]), int32_t(t[2]), -1});
  coordIndex.setValues(0, int(index.size()), index.data());
}

void setMesh(ClothEngine* engine, const TriangleMesh& mesh) {
  const std::vector<SbVec3f> points = pointsOf(mesh.vertices);
  engine->restPoints.setValues(0, int(points.size()), points.data());
  setTriangles(engine->coordIndex, mesh);
}

// The body made once, with every field set: a HumanBody makes itself again on each field
// changed, so setting five fields one by one made it five times (a second and more).
// Referenced once, for the caller.
HumanBody* madeBodyNode(const RenderRequest& request) {
  auto* body = new HumanBody;
  body->ref();
  const std::pair<SoSFFloat*, double> quiet[] = {{&body->gender, request.sex == "male" ? 1.0 : 0.0},
                                                 {&body->stature, request.body.stature},
                                                 {&body->bustGirth, request.body.bust},
                                                 {&body->waistGirth, request.body.waist}};
  for (const auto& [field, value] : quiet) {
    field->enableNotify(false);
    field->setValue(float(value));
    field->enableNotify(true);
  }
  // HumanBody's Pose lists the presets in PosePreset's order.
  body->pose.enableNotify(false);
  body->pose = int(MeasuredPoses::find(request.pose)->preset);
  body->pose.enableNotify(true);
  body->hipGirth = float(request.body.hips);  // the one change that makes it
  if (body->point.getNum() == 0) {
    body->unref();
    throw OutfitScene::BodyNotMade("the measured body could not be made");
  }
  return body;
}

// The innermost garment of a made body at rest, from its size drape (the advice's: nothing
// draped here): drawn where the drape left it.
Draped drawnSizeDrape(SoSeparator* root, const OutfitItem& item, const TriangleMesh& cut, const GarmentDrape& drape,
                      const FitMapTarget& fitMap) {
  auto* coordinates = new SoCoordinate3;
  const std::vector<SbVec3f> points = pointsOf(drape.positions);
  coordinates->point.setValues(0, int(points.size()), points.data());
  const SoMFInt32* drawn = nullptr;
  root->addChild(garment(
      item, coordinates, [&cut](SoMFInt32& field) { setTriangles(field, cut); }, fitMap, [&cut] { return cut; },
      &drawn));
  return {following(&coordinates->point), drawn};
}

// What a catalogue style is made of and how it drapes: a generator's style's own fabric and
// settings, or a sewn style's fabric from its catalogue file.
struct ItemCloth {
  std::string fabric;
  ClothParameters parameters;
  bool sewn = false;
};

ItemCloth clothOf(const OutfitItem& item, const GarmentCatalogue& catalogue) {
  if (const figment::GarmentStyle* cut = findStyle(item.style)) return {cut->fabric, sizeDrapeParameters(*cut), false};
  const CatalogueStyle* sold = catalogue.style(item.style);
  if (!sold || !sold->sewn()) throw std::invalid_argument("no catalogue style " + item.style);
  return {sold->fabric, sizeDrapeParameters(sold->fabric), true};
}

// A made body and its graded garments (the class comment).
void dressMeasured(SoSeparator* root, SoSeparator* skin, const RenderRequest& request,
                   const GarmentCatalogue& catalogue, const OutfitScene::Made& made,
                   std::vector<OutfitScene::FitMapGarment>* fitMaps, std::vector<DrapeReport>* drawn) {
  const bool kept = request.pose == "rest" && made.restBody;  // the worker keeps it between scenes
  HumanBody* body = kept ? made.restBody(request) : madeBodyNode(request);
  skin->addChild(body);
  if (!kept) body->unref();  // the scene holds it now
  const int layer = request.underwear ? HumanBody::UNDERWEAR : HumanBody::NONE;
  if (body->baseLayer.getValue() != layer) body->baseLayer = layer;  // cut once a body, drawn or not
  const Sex sex = request.sex == "male" ? Sex::Male : Sex::Female;
  std::vector<Draped> beneath;
  for (const OutfitItem& item : request.outfit) {
    const ItemCloth cloth = clothOf(item, catalogue);
    const SizeFitter::Graded& graded = made.graded(item, sex);
    FitMapTarget fitMap{fitMaps, cloth.fabric, request.fitMap, body, cloth.parameters, graded.flat};
    if (beneath.empty() && request.pose == "rest" && made.sizeDrape) {
      const GarmentDrape drape = made.sizeDrape(request, item);
      if (drawn) drawn->push_back(drape.report);
      beneath.push_back(drawnSizeDrape(root, item, graded.garment, drape, fitMap));
      continue;
    }
    ClothEngine* engine =
        gradedEngine(cloth.fabric, cloth.parameters, !beneath.empty(), cloth.sewn, bodyUnder(body, beneath));
    if (cloth.sewn) {
      // Placed round this body and sewn by the engine, as a SewingPattern node's panels are;
      // at rest it starts from its own size drape on this body (sewn, the advice's), so the
      // engine's sewing closes at once and the drape only settles it over the layers beneath
      // (planDrape moves it out over them). Sewn over a T-shirt from its placed panels, a
      // pencil skirt's waistband tore.
      UnsewnGarment cut = made.sewnCut(request, item);
      if (request.pose == "rest" && made.sizeDrape) cut.placed.vertices = made.sizeDrape(request, item).positions;
      setMesh(engine, cut.placed);
      setPanelFields(cut, engine->panelPoints, engine->seams);
      fitMap.flat = panelsAtRest(cut);
    } else {
      setMesh(engine, graded.garment);
    }
    const SoMFInt32* drawnIndex = nullptr;
    root->addChild(garment(
        item, coordinatesOf(engine), connectedTo(engine->coordIndex), fitMap, [engine] { return restMesh(*engine); },
        &drawnIndex));
    beneath.push_back({following(engine), &engine->coordIndex});
  }
}

}  // namespace

HumanBody* OutfitScene::makeBody(const RenderRequest& request) {
  return madeBodyNode(request);
}

SoSeparator* OutfitScene::build(const RenderRequest& request, const Wardrobe& wardrobe, const Made& made,
                                std::vector<FitMapGarment>* fitMaps, std::vector<DrapeReport>* drawn) {
  if (request.fitMap.empty()) fitMaps = nullptr;
  auto* root = new SoSeparator;
  addLights(root, *ShopperChoices::light(request.light));
  auto* body = new SoSeparator;
  body->addChild(material(colourOf(request.skin), 0.1f, 0.2f));
  body->addChild(hints(true));
  if (!request.mannequin()) {
    root->ref();
    root->addChild(body);
    try {
      dressMeasured(root, body, request, *wardrobe.catalogue(), made, fitMaps, drawn);
    } catch (...) {
      root->unref();  // the half-made scene goes
      throw;
    }
    root->unrefNoDelete();
    return root;
  }
  Mannequin* model = mannequin(request, wardrobe);
  body->addChild(model);
  auto* skin = new MannequinSkin;
  skin->mannequin = model;
  body->addChild(skin);
  root->addChild(body);
  std::vector<Draped> beneath;
  for (const OutfitItem& item : request.outfit) {
    const GarmentStyle& style = *ShopperChoices::style(item.style);
    const MeshFile* pattern = wardrobe.pattern(item.style);
    ClothEngine* engine = engineFor(style, !beneath.empty(), bodyUnder(model, beneath));
    restShape(engine, pattern, wardrobe.heightOrigin(), ShopperChoices::bodyFactors(request.body).height);
    engine->coordIndex.connectFrom(const_cast<SoMFInt32*>(&pattern->coordIndex));
    const SoMFInt32* drawnIndex = nullptr;
    root->addChild(garment(
        item, coordinatesOf(engine), connectedTo(pattern->coordIndex),
        {fitMaps, "jersey", request.fitMap, nullptr, ClothParameters{}, std::nullopt},  // cotton jersey
        [engine] { return restMesh(*engine); }, &drawnIndex));
    beneath.push_back({following(engine), &pattern->coordIndex});
  }
  return root;
}

void OutfitScene::paintFitMaps(const std::vector<FitMapGarment>& fitMaps) {
  for (const FitMapGarment& garment : fitMaps) {
    const TriangleMesh& rest = garment.rest;
    std::vector<Vec3> positions;
    for (int i = 0; i < garment.coordinates->point.getNum(); ++i) {
      const SbVec3f& p = garment.coordinates->point[i];
      positions.emplace_back(p[0], p[1], p[2]);
    }
    if (positions.size() != rest.vertices.size())
      throw std::runtime_error("fit map: the drape has " + std::to_string(positions.size()) + " points, the garment " +
                               std::to_string(rest.vertices.size()));
    FitInput input;
    input.rest = &rest;
    input.restShape = garment.flat ? &*garment.flat : nullptr;
    input.positions = &positions;
    const FitMapKind kind = fitMapKind(garment.kind);
    std::shared_ptr<const MeshCollider> skin;
    if (kind != FitMapKind::Stretch) {
      skin = garment.skin ? garment.skin->collider() : nullptr;
      if (!skin) throw std::runtime_error("fit map " + garment.kind + ": no skin to measure from");
      input.body = skin.get();
      input.parameters = garment.parameters;
    }
    const FabricLimits limits = fabricLimits(garment.fabric);
    std::vector<SbColor> colours;
    for (const int band : fitMapBands(input, kind, limits)) {
      const Vec3 c = fitMapColour(band);
      colours.emplace_back(float(c.x()), float(c.y()), float(c.z()));
    }
    garment.material->diffuseColor.setValues(0, int(colours.size()), colours.data());
  }
}

}  // namespace figment::serve

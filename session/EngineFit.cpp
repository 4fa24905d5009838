#include "session/EngineFit.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/engines/SoEngineOutput.h>
#include <Inventor/nodes/SoCoordinate3.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <optional>

#include "io/GarmentCatalogue.h"
#include "io/MakeHumanLibrary.h"
#include "nodes/body/HumanBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/body/MeshFile.h"
#include "nodes/cloth/CatalogueGarment.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/render/ClothingLayer.h"
#include "sim/body/BodyMeasurements.h"
#include "sim/fit/FitRegion.h"
#include "sim/fit/SizeFitter.h"

namespace figment::session {

namespace {

// The ClothEngine whose positions the Coordinate3 nearest before `index` in `group` reads.
ClothEngine* drawnEngine(SoGroup* group, int index) {
  for (int i = index - 1; i >= 0; --i) {
    SoNode* node = group->getChild(i);
    if (!node->isOfType(SoCoordinate3::getClassTypeId())) continue;
    SoEngineOutput* output = nullptr;
    if (!static_cast<SoCoordinate3*>(node)->point.getConnectedEngine(output) || !output) return nullptr;
    SoFieldContainer* container = output->getFieldContainer();
    return container && container->isOfType(ClothEngine::getClassTypeId()) ? static_cast<ClothEngine*>(container)
                                                                           : nullptr;
  }
  return nullptr;
}

SoCoordinate3* drawnCoordinates(SoGroup* group, int index) {
  for (int i = index - 1; i >= 0; --i)
    if (group->getChild(i)->isOfType(SoCoordinate3::getClassTypeId()))
      return static_cast<SoCoordinate3*>(group->getChild(i));
  return nullptr;
}

// Whether a Mannequin stands as its body mesh does: no joint turned, every size factor 1.
bool atRest(const Mannequin& mannequin) {
  for (const SoSFFloat* factor :
       {&mannequin.height, &mannequin.chest, &mannequin.waist, &mannequin.hips, &mannequin.armLength})
    if (factor->getValue() != 1.0f) return false;
  return mannequin.rotatedJoints.getNum() == 0;
}

// The mesh an engine's body is: a MeshFile, or the body MeshFile of a Mannequin at rest
// (a posed or sized one's volumes have left its mesh); else null.
const MeshFile* meshBody(const ClothEngine& engine) {
  SoNode* node = engine.body.getValue();
  if (node && node->isOfType(Mannequin::getClassTypeId()))
    node = atRest(*static_cast<Mannequin*>(node)) ? static_cast<Mannequin*>(node)->body.getValue() : nullptr;
  return node && node->isOfType(MeshFile::getClassTypeId()) ? static_cast<const MeshFile*>(node) : nullptr;
}

// The CatalogueGarment an engine's rest points are read from, or null.
const CatalogueGarment* catalogueGarment(const ClothEngine& engine) {
  SoField* master = nullptr;
  if (!engine.restPoints.getConnectedField(master) || !master) return nullptr;
  SoFieldContainer* container = master->getContainer();
  return container && container->isOfType(CatalogueGarment::getClassTypeId())
             ? static_cast<const CatalogueGarment*>(container)
             : nullptr;
}

// Each engine drawn by a ClothingLayer on a mesh body, with its layers, in scene order.
std::vector<EngineFit> drawnEngines(SoSeparator* scene) {
  SoSearchAction search;
  search.setType(ClothingLayer::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.apply(scene);
  std::vector<EngineFit> fits;
  const SoPathList& paths = search.getPaths();
  for (int p = 0; p < paths.getLength(); ++p) {
    const SoPath* path = paths[p];
    if (path->getLength() < 2 || !path->getNodeFromTail(1)->isOfType(SoGroup::getClassTypeId())) continue;
    auto* group = static_cast<SoGroup*>(path->getNodeFromTail(1));
    const int index = path->getIndexFromTail(0);
    ClothEngine* engine = drawnEngine(group, index);
    if (!engine || !meshBody(*engine)) continue;
    auto* layer = static_cast<ClothingLayer*>(path->getTail());
    auto known = std::find_if(fits.begin(), fits.end(), [engine](const EngineFit& f) { return f.engine == engine; });
    if (known == fits.end()) {
      EngineFit fit;
      fit.engine = engine;
      const SoMFVec3f& drawn = drawnCoordinates(group, index)->point;
      fit.positions.reserve(drawn.getNum());
      for (int i = 0; i < drawn.getNum(); ++i) fit.positions.emplace_back(drawn[i][0], drawn[i][1], drawn[i][2]);
      fits.push_back(std::move(fit));
      known = fits.end() - 1;
    }
    known->layers.emplace_back(group, layer);
  }
  return fits;
}

// The garment, its body and parameters of `fit.engine`; false when they do not match.
bool fillInputs(EngineFit& fit) {
  const ClothEngine& engine = *fit.engine;
  fit.name = engine.getName().getString();
  fit.rest = engine.restGarment();
  if (fit.rest.vertices.size() != fit.positions.size()) return false;
  fit.parameters = engine.clothParameters();
  fit.limits = fabricLimits(engine.material.getValue().getString());
  const MeshFile& body = *meshBody(engine);
  fit.bodyMesh = body.collisionSurface();
  fit.body = body.collider();
  // A posed HumanBody: its regions are its rest pose's, the drape carried back to them.
  if (body.isOfType(HumanBody::getClassTypeId())) {
    TriangleMesh rest = static_cast<const HumanBody&>(body).restSurface();
    if (rest.triangles == fit.bodyMesh.triangles && rest.vertices.size() == fit.bodyMesh.vertices.size() &&
        rest.vertices != fit.bodyMesh.vertices)
      fit.pose = std::make_shared<const PosedSkin>(std::move(rest), fit.bodyMesh);
    fit.motion = std::dynamic_pointer_cast<const MovingMeshCollider>(body.bodyCollider());
  }
  // The shipped catalogue's garments only: the one a verdict's intended fit is graded from.
  if (const CatalogueGarment* garment = catalogueGarment(engine);
      garment && garment->point.getNum() > 0 && garment->catalogue.getValue().getLength() == 0)
    fit.garment = garment->garment.getValue().getString();
  return fit.body != nullptr;
}

bool isFemale(const ClothEngine& engine) {
  const SoNode* node = engine.body.getValue();
  return !(node && node->isOfType(HumanBody::getClassTypeId()) &&
           static_cast<const HumanBody*>(node)->gender.getValue() > 0.5f);
}

// The body's regions the garment's style tells (all of them for a garment not of the
// catalogue), measured; none when the body (a posed one at rest) cannot be measured as a
// standing human.
void measureRegions(EngineFit& fit, const std::vector<std::string>* told) {
  const TriangleMesh& standing = fit.pose ? fit.pose->rest() : fit.bodyMesh;
  BodyMeasurements measured;
  try {
    measured = measureBody(standing);
  } catch (const std::exception&) {
    return;
  }
  std::vector<FitRegion> regions;
  for (FitRegion& region : bodyRegions(standing, measured, isFemale(*fit.engine)))
    if (!told || std::find(told->begin(), told->end(), region.name) != told->end())
      regions.push_back(std::move(region));
  fit.regions = measureFit(fit.input(), regions);
}

// Verdicts against the garment's size draped on its own chart body, as figment-size's.
void judgeRegions(EngineFit& fit, const CatalogueItem& item, const SizeChart& chart, MakeHumanLibrary& human) {
  if (human.dir().empty()) return;
  SizeFitter fitter(human.model(), chart, *item.style);
  const std::vector<RegionFit>& own = fitter.ownFit(item.sex, item.size);
  std::vector<RegionFit> intended;
  for (const RegionFit& region : fit.regions) {
    const auto match = std::find_if(own.begin(), own.end(), [&](const RegionFit& o) { return o.name == region.name; });
    intended.push_back(match != own.end() ? *match : RegionFit{region.name});
  }
  const VerdictRule rule{fit.limits};
  for (size_t i = 0; i < fit.regions.size(); ++i) fit.verdicts.push_back(judge(fit.regions[i], intended[i], rule));
  fit.text = shopperText(fit.regions, intended, fit.verdicts, rule);
}

}  // namespace

std::vector<EngineFit> measureEngineFits(SoSeparator* scene, bool regions, MakeHumanLibrary* verdicts) {
  std::vector<EngineFit> fits;
  for (EngineFit& fit : drawnEngines(scene)) {
    if (!fillInputs(fit)) continue;
    // A fit that cannot be told (a body MakeHuman cannot make for the verdict's chart
    // size, a catalogue that no longer reads) leaves what was measured: the drape stands.
    try {
      std::optional<GarmentCatalogue> shop;
      std::optional<CatalogueItem> item;
      if (!fit.garment.empty()) {
        shop.emplace(defaultCataloguePath());
        item = shop->resolve(fit.garment);
      }
      if (regions) measureRegions(fit, item ? &item->regions : nullptr);
      // Verdicts for a generator's garment only: a pattern style's size on its own chart
      // body is sewn, which SizeFitter's pattern fitter does (figment-size), not yet here.
      if (regions && verdicts && item && item->style && !fit.regions.empty())
        judgeRegions(fit, *item, shop->chart(), *verdicts);
    } catch (const std::exception&) {
      fit.verdicts.clear();
      fit.text.clear();
    }
    fits.push_back(std::move(fit));
  }
  return fits;
}

FitInput EngineFit::input() const {
  FitInput in;
  in.rest = &rest;
  in.positions = &positions;
  in.body = body.get();
  in.parameters = parameters;
  in.pose = pose.get();
  return in;
}

}  // namespace figment::session

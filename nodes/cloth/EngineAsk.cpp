#include "nodes/cloth/EngineAsk.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "io/ProgressiveScript.h"
#include "io/TradeoffTable.h"
#include "nodes/SceneFiles.h"
#include "nodes/body/CollisionBody.h"
#include "nodes/body/CollisionGroup.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

BodyDescription describe(const SoNode* body) {
  const CollisionBody* collisionBody = asCollisionBody(body);
  if (!collisionBody) return {};
  CollisionBody::Description d = collisionBody->describeBody();
  return {std::move(d.kind), std::move(d.counts)};
}

// The Mannequin's own triangles stand for it only in its rest pose and size: they are
// not posed. "" in its rest pose and size, else how it differs ("posed (rotatedJoints),
// sized (height 0.98)").
std::string poseOrSize(const Mannequin& m) {
  std::string changed;
  const auto add = [&](const std::string& what) { changed += (changed.empty() ? "" : ", ") + what; };
  if (m.rotatedJoints.getNum() > 0) add("posed (rotatedJoints)");
  const std::pair<const char*, const SoSFFloat*> factors[] = {
      {"height", &m.height}, {"chest", &m.chest}, {"waist", &m.waist}, {"hips", &m.hips}, {"armLength", &m.armLength}};
  for (const auto& [name, field] : factors)
    if (field->getValue() != 1.0f) add(std::string("sized (") + name + " " + formatNumber(field->getValue()) + ")");
  return changed;
}

void offerMannequinsBodies(const Mannequin& mannequin, DrapeBody& body) {
  body.jointed = true;
  body.poseOrSize = poseOrSize(mannequin);
  const Mannequin* m = &mannequin;
  body.withExactParts = [m](const std::vector<int>& parts) { return m->colliderWithExactParts(parts); };
  if (!mannequin.body.getValue()) return;
  body.trianglesDescription = describe(mannequin.body.getValue());
  body.triangles = [m] {
    const CollisionBody* exact = asCollisionBody(m->body.getValue());
    if (!exact) throw std::runtime_error("tolerance: the Mannequin's body is no mesh to collide with");
    return exact->bodyCollider();
  };
}

}  // namespace

std::string tradeoffTablePath() {
  if (const char* path = std::getenv("FIGMENT_TRADEOFF_TABLE"); path && *path) return path;
  std::error_code ec;
  if (std::filesystem::exists(FIGMENT_TRADEOFF_TABLE_INSTALLED, ec)) return FIGMENT_TRADEOFF_TABLE_INSTALLED;
  return FIGMENT_TRADEOFF_TABLE_SOURCE;
}

DrapeReport reportBeforeDrape(const ClothEngine& engine) {
  DrapeReport report;
  report.method = methodFromFields(engine);
  report.strainLimit = engine.strainLimit.getValue();
  report.maxTime = engine.maxTime.getValue();
  report.body = describe(engine.body.getValue());
  return report;
}

DrapeBody drapeBodyFromField(const SoSFNode& field) {
  DrapeBody body;
  body.collider = colliderFromBody(field);
  SoNode* node = field.getValue();
  body.description = describe(node);
  if (node && node->isOfType(Mannequin::getClassTypeId())) offerMannequinsBodies(*static_cast<Mannequin*>(node), body);
  if (node && node->isOfType(CollisionGroup::getClassTypeId()))
    body.beneath = static_cast<const CollisionGroup*>(node)->layersCollider();  // the garments under this one
  return body;
}

DrapeAsk drapeAskFromFields(const ClothEngine& engine, const std::vector<std::string>& sceneDirectories,
                            std::optional<MethodTable>& table) {
  DrapeAsk ask;
  ask.garment = garmentFromFields(engine.restPoints, engine.coordIndex);
  ask.parameters = parametersFromFields(engine);
  ask.tolerance = engine.tolerance.getValue();
  requireNonNegative("tolerance", ask.tolerance);
  ask.body = drapeBodyFromField(engine.body);
  if (ask.tolerance > 0.0) {
    table = readTradeoffTable(tradeoffTablePath());
    ask.table = &*table;
  } else if (const std::string script = engine.progressiveScript.getValue().getString(); !script.empty()) {
    const std::string path = resolveSceneFile(script, sceneDirectories);
    if (path.empty()) throw std::runtime_error("progressiveScript \"" + script + "\" not found");
    ask.progressive = readProgressiveScript(path, ask.garment);
    ask.schedule = {engine.beginLevel.getValue(), engine.endLevel.getValue(), engine.splitRate.getValue()};
  }
  ask.sewing = sewingFromFields(engine.panelPoints, engine.seams, ask.garment.vertices.size());
  return ask;
}

}  // namespace figment

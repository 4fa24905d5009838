#include "nodes/cloth/ToleranceChoice.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "nodes/body/CollisionBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/collision/VolumeSetCollider.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

// The count of `what` in a body's description (0 when it has none).
int countOf(const CollisionBody::Description& d, const std::string& what) {
  for (const auto& [name, count] : d.counts)
    if (name == what) return count;
  return 0;
}

// The Mannequin the engine drapes on, when it is one.
const Mannequin* mannequinOf(const ClothEngine& engine) {
  SoNode* body = engine.body.getValue();
  return body && body->isOfType(Mannequin::getClassTypeId()) ? static_cast<const Mannequin*>(body) : nullptr;
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

// "" when the engine can drape by `c`; else why not, as a phrase.
std::string whyUnusable(const ClothEngine& engine, const MeasuredConfiguration& c) {
  if (c.resolution != 1.0) return "measured on a resampled garment";
  const Mannequin* mannequin = mannequinOf(engine);
  if (!mannequin) return "the body is no Mannequin";
  const CollisionBody::Description d = mannequin->describeBody();
  const int capsules = countOf(d, "capsule_volumes"), radial = countOf(d, "radial_volumes"),
            exact = countOf(d, "exact_parts");
  const bool radialOnly = radial > 0 && capsules == 0;
  if ((c.body == "triangles" || c.body == "mix") && !mannequin->body.getValue())
    return "the Mannequin has no body mesh";
  if (c.body == "triangles") {
    const std::string changed = poseOrSize(*mannequin);
    return changed.empty() ? "" : "the Mannequin's triangles are its rest pose and size, and it is " + changed;
  }
  if (c.body == "mix") return radialOnly ? "" : "the Mannequin's volumes are not all radial";
  if (c.body == "volumes") return radialOnly && exact == 0 ? "" : "the Mannequin's volumes are not all radial";
  if (c.body == "capsules")
    return capsules > 0 && radial == 0 && exact == 0 ? "" : "the Mannequin's volumes are not all capsules";
  return "an unknown body \"" + c.body + "\"";
}

// The configurations within `tolerance` faster than `picked` (all within it, without
// one) that the engine cannot use, fastest first, each with why.
std::string passedOver(const ClothEngine& engine, const std::vector<MeasuredConfiguration>& table, double tolerance,
                       const std::optional<MeasuredConfiguration>& picked) {
  std::vector<const MeasuredConfiguration*> faster;
  for (const MeasuredConfiguration& c : table)
    if (c.worstMeanDeviation <= tolerance && (!picked || c.totalWall < picked->totalWall) &&
        !whyUnusable(engine, c).empty())
      faster.push_back(&c);
  std::sort(faster.begin(), faster.end(), [](auto* a, auto* b) { return a->totalWall < b->totalWall; });
  std::string text;
  for (const MeasuredConfiguration* c : faster)
    text += (text.empty() ? "" : "; ") + c->label() + " (" + whyUnusable(engine, *c) + ")";
  return text;
}

}  // namespace

std::string tradeoffTablePath() {
  if (const char* path = std::getenv("FIGMENT_TRADEOFF_TABLE"); path && *path) return path;
  std::error_code ec;
  if (std::filesystem::exists(FIGMENT_TRADEOFF_TABLE_INSTALLED, ec)) return FIGMENT_TRADEOFF_TABLE_INSTALLED;
  return FIGMENT_TRADEOFF_TABLE_SOURCE;
}

std::vector<int> partsWhereGarmentMeets(const Mannequin& mannequin, const std::vector<Vec3>& garmentStart) {
  const auto* volumes = dynamic_cast<const VolumeSetCollider*>(mannequin.collider().get());
  return volumes ? volumes->partsWithin(garmentStart, kExactPartReach) : std::vector<int>{};
}

ToleranceChoice chooseForTolerance(const ClothEngine& engine, const TriangleMesh& garment,
                                   ClothParameters& parameters) {
  const double tolerance = engine.tolerance.getValue();
  const std::vector<MeasuredConfiguration> table = readTradeoffTable(tradeoffTablePath());
  const std::optional<MeasuredConfiguration> picked =
      fastestWithin(table, tolerance, [&](const MeasuredConfiguration& c) { return whyUnusable(engine, c).empty(); });
  const std::string refused = passedOver(engine, table, tolerance, picked);
  if (!picked)
    throw std::runtime_error("tolerance = " + formatNumber(tolerance) + ": no configuration measured within it (" +
                             tradeoffTablePath() + ") suits this body" + (refused.empty() ? "" : ": " + refused));
  applyMethod(picked->method, parameters);
  parameters.validate();
  ToleranceChoice choice{*picked, nullptr, refused};
  const Mannequin* mannequin = mannequinOf(engine);
  if (picked->body == "triangles") {
    const CollisionBody* exact = asCollisionBody(mannequin->body.getValue());
    if (!exact) throw std::runtime_error("tolerance: the Mannequin's body is no mesh to collide with");
    choice.body = exact->bodyCollider();
  } else if (picked->body == "mix") {
    choice.body = mannequin->colliderWithExactParts(partsWhereGarmentMeets(*mannequin, garment.vertices));
  } else {
    choice.body = colliderFromBody(engine.body);
  }
  return choice;
}

}  // namespace figment

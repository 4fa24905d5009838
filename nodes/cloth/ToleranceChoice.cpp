#include "nodes/cloth/ToleranceChoice.h"

#include "nodes/body/CollisionBody.h"
#include "nodes/body/Mannequin.h"
#include "nodes/cloth/ClothEngine.h"
#include "nodes/cloth/ClothEngineInputs.h"
#include "sim/collision/VolumeSetCollider.h"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

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
// not posed.
bool restPoseAndSize(const Mannequin& m) {
  return m.rotatedJoints.getNum() == 0 && m.height.getValue() == 1.0f && m.chest.getValue() == 1.0f &&
         m.waist.getValue() == 1.0f && m.hips.getValue() == 1.0f && m.armLength.getValue() == 1.0f;
}

bool usable(const ClothEngine& engine, const MeasuredConfiguration& c) {
  if (c.resolution != 1.0) return false;
  const Mannequin* mannequin = mannequinOf(engine);
  if (!mannequin) return false;
  const CollisionBody::Description d = mannequin->describeBody();
  const int capsules = countOf(d, "capsule_volumes"), radial = countOf(d, "radial_volumes"),
            exact = countOf(d, "exact_parts");
  if (c.body == "triangles") return mannequin->body.getValue() && restPoseAndSize(*mannequin);
  if (c.body == "volumes") return radial > 0 && capsules == 0 && exact == 0;
  if (c.body == "capsules") return capsules > 0 && radial == 0 && exact == 0;
  if (c.body == "mix") return mannequin->body.getValue() && radial > 0 && capsules == 0;
  return false;
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

ToleranceChoice chooseForTolerance(const ClothEngine& engine, const TriangleMesh& garment, ClothParameters& parameters) {
  const double tolerance = engine.tolerance.getValue();
  const std::vector<MeasuredConfiguration> table = readTradeoffTable(tradeoffTablePath());
  const std::optional<MeasuredConfiguration> picked =
      fastestWithin(table, tolerance, [&](const MeasuredConfiguration& c) { return usable(engine, c); });
  if (!picked)
    throw std::runtime_error("tolerance = " + std::to_string(tolerance) + ": no configuration measured within it (" +
                             tradeoffTablePath() + ") suits this body");
  applyMethod(picked->method, parameters);
  parameters.validate();
  ToleranceChoice choice{*picked, nullptr};
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

#include "sim/drape/MethodChoice.h"

#include <algorithm>
#include <stdexcept>

#include "sim/collision/VolumeSetCollider.h"
#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

// The configurations within `tolerance` faster than `picked` (all within it, without
// one) that the body cannot use, fastest first, each with why.
std::string passedOver(const DrapeBody& body, const std::vector<MeasuredConfiguration>& table, double tolerance,
                       const std::optional<MeasuredConfiguration>& picked) {
  std::vector<const MeasuredConfiguration*> faster;
  for (const MeasuredConfiguration& c : table)
    if (c.worstMeanDeviation <= tolerance && (!picked || c.totalWall < picked->totalWall) &&
        !whyUnusable(body, c).empty())
      faster.push_back(&c);
  std::sort(faster.begin(), faster.end(), [](auto* a, auto* b) { return a->totalWall < b->totalWall; });
  std::string text;
  for (const MeasuredConfiguration* c : faster)
    text += (text.empty() ? "" : "; ") + c->label() + " (" + whyUnusable(body, *c) + ")";
  return text;
}

}  // namespace

std::vector<int> partsWhereGarmentMeets(const Collider& volumes, const std::vector<Vec3>& garmentStart) {
  const auto* set = dynamic_cast<const VolumeSetCollider*>(&volumes);
  return set ? set->partsWithin(garmentStart, kExactPartReach) : std::vector<int>{};
}

std::string whyUnusable(const DrapeBody& body, const MeasuredConfiguration& c) {
  if (c.resolution != 1.0) return "measured on a resampled garment";
  if (!body.jointed) return "the body is no Mannequin";
  const BodyDescription& d = body.description;
  const int capsules = d.count("capsule_volumes"), radial = d.count("radial_volumes"), exact = d.count("exact_parts");
  const bool radialOnly = radial > 0 && capsules == 0;
  if ((c.body == "triangles" || c.body == "mix") && !body.triangles) return "the Mannequin has no body mesh";
  if (c.body == "triangles")
    return body.poseOrSize.empty()
               ? ""
               : "the Mannequin's triangles are its rest pose and size, and it is " + body.poseOrSize;
  if (c.body == "mix") return radialOnly ? "" : "the Mannequin's volumes are not all radial";
  if (c.body == "volumes") return radialOnly && exact == 0 ? "" : "the Mannequin's volumes are not all radial";
  if (c.body == "capsules")
    return capsules > 0 && radial == 0 && exact == 0 ? "" : "the Mannequin's volumes are not all capsules";
  return "an unknown body \"" + c.body + "\"";
}

MethodChoice chooseMethod(const MethodTable& table, double tolerance, const DrapeBody& body,
                          const std::vector<Vec3>& garmentStart) {
  const std::vector<MeasuredConfiguration>& rows = table.configurations;
  const std::optional<MeasuredConfiguration> picked =
      fastestWithin(rows, tolerance, [&](const MeasuredConfiguration& c) { return whyUnusable(body, c).empty(); });
  const std::string refused = passedOver(body, rows, tolerance, picked);
  if (!picked)
    throw std::runtime_error("tolerance = " + formatNumber(tolerance) + ": no configuration measured within it (" +
                             table.source + ") suits this body" + (refused.empty() ? "" : ": " + refused));
  MethodChoice choice{*picked, body.collider, body.description, refused};
  if (picked->body == "triangles") {
    choice.body = body.triangles();
    choice.bodyDescription = body.trianglesDescription;
  } else if (picked->body == "mix") {
    choice.body =
        body.withExactParts(body.collider ? partsWhereGarmentMeets(*body.collider, garmentStart) : std::vector<int>{});
  }
  return choice;
}

}  // namespace figment

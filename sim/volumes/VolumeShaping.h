#pragma once
// The collision volumes of a whole body (paper §3): capsules (§3.1) or radial depth
// volumes (§3.2) for every part of its skeleton, each enclosing its part's vertices
// (§3.3). The body is cut into parts by splitIntoParts (sim/body/BodyParts.h).
//
// Capsules: the genetic fit (sim/volumes/CapsuleShaping.h) on the part's vertices (at most 300 of
// them, evenly taken), then grown to enclose all of them. Where one capsule cannot fit
// (its mean gap over the part's vertices is above 8 mm, as for the feet and the chest)
// the part is split in two at the median of its vertices along the capsule's axis and
// each half is shaped the same way (the paper's split of feet and chest, §3.3), up to
// 4 capsules a part; a split is kept only when it lowers the part's mean gap.
// Radial depth volumes: shapeRadialPart (the best of three axes, least-squares envelope
// of K harmonics per section, per-section enclosure). A part whose sections are not
// star-shaped about the axis leaves vertices hidden behind others, deep inside the
// volume: where the radial volume's mean gap is above 8 mm, the part's capsules are
// shaped too and, where their mean gap (each vertex's depth in the deepest capsule
// holding it) is smaller, the part falls back to them (kind Capsule).
// Sub-volumes share their part's name, so posing by part still works.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/body/BodyParts.h"
#include "sim/body/Skeleton.h"
#include "sim/collision/Capsule.h"
#include "sim/collision/RadialDepth.h"

namespace figment {

struct CollisionVolumeParameters {
  std::string part;  // a skeleton part name (humanoidSkeleton's parts); sub-volumes share their part's name
  enum class Kind { Capsule, Radial } kind = Kind::Capsule;
  CapsuleParameters capsule;     // when kind == Capsule
  RadialDepthParameters radial;  // when kind == Radial
};

struct VolumeShapingOptions {
  int harmonics = 8;             // K, the default the collision bench's targets are measured at
  double sectionSpacing = 0.02;  // m
  uint64_t seed = 1;
  // Called before each part is shaped (a whole body's volumes take seconds to minutes):
  // the part's name, its index among the parts shaped (from 0) and how many there are.
  std::function<void(const std::string& part, int index, int count)> progress;
};

// One or more capsules per part (every part of skeleton.parts gets at least one volume);
// each encloses its vertices.
std::vector<CollisionVolumeParameters> shapeCapsules(const TriangleMesh& body, const Skeleton& skeleton,
                                                     const VolumeShapingOptions& options = {});
// Radial depth volumes per part; parts that a radial volume cannot suit fall back to
// capsules (kind Capsule).
std::vector<CollisionVolumeParameters> shapeRadialVolumes(const TriangleMesh& body, const Skeleton& skeleton,
                                                          const VolumeShapingOptions& options = {});

// The same, for parts already cut (splitIntoParts); the bench measures these.
std::vector<CollisionVolumeParameters> shapePartCapsules(const PartMesh& part,
                                                         const VolumeShapingOptions& options = {});
std::vector<CollisionVolumeParameters> shapePartRadial(const PartMesh& part, const VolumeShapingOptions& options = {});

// The signed distance of p to one volume (< 0 inside), by its nearest().
double signedDistance(const CollisionVolumeParameters& volume, const Vec3& p);

}  // namespace figment

#pragma once
// Internal to figment_nodes (not installed): turns a ClothEngine's fields into the
// simulation's types. Each function throws std::invalid_argument naming the field and
// value when an input cannot be used.

#include <memory>
#include <optional>

#include "sim/cloth/ClothParameters.h"
#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"
#include "sim/drape/DrapeMethod.h"
#include "sim/drape/GarmentDrape.h"

class ClothEngine;
class SoMFInt32;
class SoMFVec2f;
class SoMFVec3f;
class SoSFNode;

namespace figment {

// The garment: restPoints (m) and the faces of coordIndex, -1 separated, polygons split
// into triangles as a fan (0 1 2, 0 2 3, ...). Empty faces (-1 -1) are skipped.
// `pointsName` names the points field in errors.
TriangleMesh garmentFromFields(const SoMFVec3f& restPoints, const SoMFInt32& coordIndex,
                               const char* pointsName = "restPoints");

// The sewing a pattern's garment asks for: its panel points (m) and seam pairs; nothing
// when `seams` is empty. Throws naming the field for a count that does not match the rest
// points, an odd seams count or an index out of range.
std::optional<DrapeSewing> sewingFromFields(const SoMFVec2f& panelPoints, const SoMFInt32& seams, size_t restPoints);

// The material: a preset named in `material` with the four material fields the scene
// wrote over it, or those four fields alone. Throws for an unknown preset.
Material materialFromFields(const ClothEngine& engine);

// The method the fields name, not validated: what a report says before any drape was
// planned (the drape failed first).
DrapeMethod methodFromFields(const ClothEngine& engine);

// Material and run parameters from the engine's fields, validated.
ClothParameters parametersFromFields(const ClothEngine& engine);

// The collider of the node in `body` (a figment::CollisionBody: a MeshFile's exact
// collider, a Mannequin's posed volumes, a CollisionGroup's union); null for NULL.
std::shared_ptr<const Collider> colliderFromBody(const SoSFNode& body);

}  // namespace figment

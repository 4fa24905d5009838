#pragma once
// Internal to figment_nodes (not installed): a ClothEngine's garment checked against its
// body before it drapes (the geometry: sim/drape/GarmentStart.h), in words that name the
// node and field to change, their value and the fix to try, as the body tools do for a
// body (tools/ToolMain.h). docs/bad-input.md lists each line and its test.

#include <string>

#include "sim/collision/Collider.h"
#include "sim/core/TriangleMesh.h"

class ClothEngine;

namespace figment {

// Throws std::invalid_argument with one line where the drape cannot be right: a garment
// in another unit ("... is 92 m across, 55 times the body's 1.66 m: ...: try metresPerUnit
// 0.01") or lying on its side ("try upAxis Z"). Returns
// the warning where it may be wrong ("" when none): some of its nodes start inside the
// body, or its faces wind clockwise seen from outside. `body` may be null.
std::string garmentStartWarning(const ClothEngine& engine, const TriangleMesh& garment, const Collider* body);

}  // namespace figment

#pragma once
// Internal to figment_nodes (not installed): what a ClothEngine's fields ask of a drape
// (sim/drape/DrapePlan.h's DrapeAsk), and the body node as the plan needs it. Each throws
// std::invalid_argument naming the field and value, or std::runtime_error naming the file,
// that cannot be used.

#include <optional>
#include <string>
#include <vector>

#include "sim/drape/DrapePlan.h"

class ClothEngine;
class SoSFNode;

namespace figment {

// The table a tolerance reads: $FIGMENT_TRADEOFF_TABLE, else the installed one, else the
// source tree's docs/tradeoff-table.csv.
std::string tradeoffTablePath();

// The node in `body` as a drape's body (a figment::CollisionBody: a MeshFile, a Mannequin,
// a CollisionGroup; NULL for nothing). A Mannequin is jointed: its own triangles (its
// `body` mesh) and its volumes with parts by their triangles are offered to a tolerance.
// The functions it holds use the Mannequin node: plan and drape while it is alive.
DrapeBody drapeBodyFromField(const SoSFNode& body);

// What a report says before any drape was planned (the drape may fail first): the method,
// strainLimit and maxTime the fields name, not validated, and what the body node is (kind
// "none" for NULL or a node that is no collision body).
DrapeReport reportBeforeDrape(const ClothEngine& engine);

// The drape `engine`'s fields ask for: its garment, parameters, body, tolerance (with
// `table`, read here when the tolerance is > 0), progressive script (looked up in
// `sceneDirectories`; not with a tolerance) and sewing.
DrapeAsk drapeAskFromFields(const ClothEngine& engine, const std::vector<std::string>& sceneDirectories,
                            std::optional<MethodTable>& table);

}  // namespace figment

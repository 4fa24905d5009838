#pragma once
// The mesh reconstruction script of a progressive mesh (paper §4): its vertex splits,
// coarsest first, as a text file (format: docs/progressive-script.md). The garment
// itself is not in it: a script belongs to one garment, checked by its vertex and face
// counts and a hash of its rest coordinates (as floats, as a scene holds them) and faces.

#include <cstdint>
#include <string>

#include "sim/progressive/ProgressiveMesh.h"

namespace figment {

std::uint64_t garmentHash(const TriangleMesh& garment);

// Writes atomically; throws std::runtime_error("<path>: <reason>").
void writeProgressiveScript(const ProgressiveMesh& mesh, const std::string& path);

// Reads the splits of `garment`'s script. Throws std::runtime_error("<path>: <reason>")
// when the file cannot be read, is malformed (naming the line), or belongs to another
// garment (naming the counts or the hash).
ProgressiveMesh readProgressiveScript(const std::string& path, const TriangleMesh& garment);

}  // namespace figment

#pragma once
// Mesh files that make assimp itself misbehave, refused before assimp is given them. Each case
// is a bug of the assimp Debian ships (5.2), found by tests/fuzz/fuzz_mesh, that we cannot fix
// there; a later assimp may not need the check.

#include <string>

namespace figment {

// "" when assimp may read the file at `path`; else one line saying what is wrong, e.g.
// "PLY header without end_header in its first 64 KiB (assimp 5.2 may never finish reading it)".
// Today's case: a PLY file (named ".ply", or whose first word is "ply") whose header is not
// clean text of PLY keywords ending in end_header. assimp 5.2's PLY reader loops forever on a
// header without its end, and on one with a control byte inside a line (fuzz_mesh found both).
std::string assimpHazard(const std::string& path);

}  // namespace figment

#pragma once
// Mesh files that make assimp itself misbehave, refused before assimp is given them. Each case
// is a bug of the assimp Debian ships (5.2), found by tests/fuzz/fuzz_mesh, that we cannot fix
// there; a later assimp may not need the check.

#include <string>

struct aiScene;

namespace figment {

// "" when assimp may read the file at `path`; else one line saying what is wrong, e.g.
// "PLY header without end_header in its first 64 KiB (assimp 5.2 may never finish reading it)".
// Today's case: a PLY file (named ".ply", or whose first word is "ply") whose header is not
// clean text of PLY keywords ending in end_header, or whose element counts are not whole
// numbers the file's bytes can hold. assimp 5.2's PLY reader loops forever on a header without
// its end, on one with a control byte inside a line, and (for hours) on a count of billions in a
// small file (fuzz_mesh found all three).
// And an OFF file (named ".off", or starting "off") whose lines do not match its counts, or
// whose faces name no vertex: assimp 5.2's OFF reader then writes out of bounds (SEGV).
std::string assimpHazard(const std::string& path);

// Sets each mesh's mPrimitiveTypes from the faces it has. assimp 5.2's PLY reader can flag a
// mesh as holding polygons when it holds none (a face list shorter than its header said), and
// its Triangulate step then aborts the program (ai_assert "numOut != pMesh->mNumFaces", found
// by fuzz_mesh). Called between reading a file and post-processing it.
void correctPrimitiveTypes(aiScene& scene);

}  // namespace figment

#pragma once
// Writes a mesh (metres, y up) to a file others can read: the garments our tools make.

#include <string>

#include "sim/core/TriangleMesh.h"

namespace figment {

// Writes `mesh` as a Wavefront OBJ without a material file, through assimp's exporter
// ("objnomtl"): positions (9 significant digits) and triangles, no normals or texture
// coordinates. The exporter lists vertices in the order the triangles first use them and
// writes only used ones; a mesh already numbered that way reads back (importMesh) with
// the same indices. The file appears complete or not at all: it is written under a
// temporary name next to `path` and renamed on success.
// Throws std::runtime_error("<path>: <reason>") when the mesh is empty or the file cannot
// be written.
void exportObj(const TriangleMesh& mesh, const std::string& path);

// Writes `mesh` as an Open Inventor 2.1 ASCII scene Coin reads (a made body for
// figment-view or a scene's File node): a Separator holding ShapeHints (counter-clockwise,
// solid), a Coordinate3 with the vertices (9 significant digits, in order) and an
// IndexedFaceSet of the triangles. Coin's text, written without Coin; whole or not at all.
// Throws std::runtime_error("<path>: <reason>") as exportObj does.
void exportIv(const TriangleMesh& mesh, const std::string& path);

}  // namespace figment

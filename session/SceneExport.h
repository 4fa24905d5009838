#pragma once
// A draped scene's garments (and, if asked, everything else it draws: the body) as
// meshes a modelling program or a web viewer reads: glTF 2.0 (GLB or .gltf) or OBJ.
// Written once for every front end: figment-view --export writes a file, a service
// answers with GLB bytes made in memory.

#include <string>
#include <vector>

#include "io/MeshSetExport.h"

class SoNode;

namespace figment::session {

// What an export holds besides the garments.
struct ExportContent {
  bool body = false;  // every other shape the scene draws as triangles: the body's skin
};

// The meshes of `scene` as it now stands (drape it first: SceneSession::drape), in the
// scene's world frame (metres, y up), traversed as Coin draws it (a Switch's hidden
// child is left out; so is a shape drawn as lines or points, a DrawStyle's edge overlay):
//   - one garment per face set that draws a drape: every ClothingLayer, and every
//     IndexedFaceSet whose coordinates are a Coordinate3 fed by a ClothEngine. Its
//     vertices are the coordinates its coordIndex uses, in their order (all of a
//     garment's nodes: one vertex each), its triangles its faces fanned, counter-
//     clockwise from the front (as ShapeHints orders them), its normals smooth (area
//     weighted, as ClothingLayer draws them); two-sided unless ShapeHints says SOLID.
//   - with `content.body`, one mesh per other shape that gives triangles (a
//     MannequinSkin: its triangles as Coin generates them, vertices shared where
//     position and normal agree).
// Each is named for the nearest DEF name above it (else garment-N, body-N), coloured by the Material's first
// diffuse colour and transparency in force there. Throws std::runtime_error naming the
// node for a face index past its coordinates.
std::vector<ColouredMesh> sceneMeshes(SoNode* scene, const ExportContent& content);

// Writes sceneMeshes() to `path` (.glb, .gltf or .obj, by its extension; exportMeshSet):
// "" or one line saying why not ("unknown extension ...", "nothing to export: the scene
// draws no garment", "cannot make the folder ..."). Nothing is left on failure; on
// success `written` (when given) lists the files, `path` first (a .gltf's .bin, an
// OBJ's .mtl after it).
std::string exportScene(SoNode* scene, const ExportContent& content, const std::string& path,
                        std::vector<std::string>* written = nullptr);

// The same meshes as one GLB file's bytes; empty, with `error` one line, on failure.
std::vector<unsigned char> exportGlb(SoNode* scene, const ExportContent& content, std::string& error);

}  // namespace figment::session

#pragma once
// Several coloured meshes (metres, y up) in one file others read: a draped outfit for
// Blender or a web viewer (glTF 2.0, binary or text, or Wavefront OBJ with its .mtl).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

// One mesh of the set, with its own material.
struct ColouredMesh {
  std::string name;               // the glTF node, mesh and material name; the OBJ group
  TriangleMesh mesh;              // m, y up; triangles counter-clockwise seen from the front
  std::vector<Vec3> normals;      // one unit vector per vertex
  std::array<float, 3> colour{};  // diffuse (glTF base colour), each 0..1
  float opacity = 1.0f;           // 0..1
  bool twoSided = false;          // cloth is seen from both sides (glTF doubleSided)
};

enum class MeshSetFormat { Glb, Gltf, Obj };

// The format a file name's extension asks for: .glb, .gltf or .obj (any case); nullopt
// otherwise.
std::optional<MeshSetFormat> meshSetFormatOf(const std::string& path);

// Writes `meshes` through assimp's exporter: one glTF node and mesh each, or one OBJ
// group each with a material in the .mtl beside it (a .gltf gets its .bin beside it).
// The files appear complete or not at all (writeFilesAtomically); `written`, when
// given, lists them, `path` first. Throws std::runtime_error("<path>: <reason>") for an
// unknown extension, an empty set, a mesh without triangles, an index out of range, a
// normal count that is not the vertex count, or a file that cannot be written.
void exportMeshSet(const std::vector<ColouredMesh>& meshes, const std::string& path,
                   std::vector<std::string>* written = nullptr);

// The same set as the bytes of one GLB file, made in memory (a service's response).
// Throws std::runtime_error("<reason>") as above.
std::vector<unsigned char> glbOfMeshSet(const std::vector<ColouredMesh>& meshes);

}  // namespace figment

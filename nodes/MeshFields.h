#pragma once
// A triangle mesh into the fields of the nodes that offer one (MeshFile, SewingPattern):
// points in metres and coordIndex with each triangle ended by -1, the form ClothEngine and
// ClothingLayer read.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec3f.h>

#include "sim/core/TriangleMesh.h"

namespace figment {

void setMeshFields(const TriangleMesh& mesh, SoMFVec3f& points, SoMFInt32& coordIndex);

}  // namespace figment

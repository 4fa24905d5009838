#pragma once
// A triangle mesh into the fields of the nodes that offer one (MeshFile, SewingPattern):
// points in metres and coordIndex with each triangle ended by -1, the form ClothEngine and
// ClothingLayer read; and a cut pattern's panel coordinates and seams (SewingPattern,
// CatalogueGarment), the form ClothEngine's panelPoints and seams read.

#include <Inventor/fields/SoMFInt32.h>
#include <Inventor/fields/SoMFVec2f.h>
#include <Inventor/fields/SoMFVec3f.h>

#include "sim/core/TriangleMesh.h"
#include "sim/pattern/UnsewnGarment.h"

namespace figment {

void setMeshFields(const TriangleMesh& mesh, SoMFVec3f& points, SoMFInt32& coordIndex);
// Each node's panel coordinates (m) and the seams' node pairs, two indices a pair: outputs,
// flagged default so that they are never written to a file.
void setPanelFields(const UnsewnGarment& cut, SoMFVec2f& panelPoints, SoMFInt32& seams);
// The same outputs empty: nothing to sew.
void clearPanelFields(SoMFVec2f& panelPoints, SoMFInt32& seams);

}  // namespace figment

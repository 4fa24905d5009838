#include "nodes/MeshFields.h"

namespace figment {

void setMeshFields(const TriangleMesh& mesh, SoMFVec3f& points, SoMFInt32& coordIndex) {
  points.setNum(static_cast<int>(mesh.vertices.size()));
  SbVec3f* p = points.startEditing();
  for (const auto& v : mesh.vertices) *p++ = SbVec3f(float(v.x()), float(v.y()), float(v.z()));
  points.finishEditing();
  coordIndex.setNum(static_cast<int>(4 * mesh.triangles.size()));
  int32_t* c = coordIndex.startEditing();
  for (const auto& t : mesh.triangles) {
    *c++ = t[0];
    *c++ = t[1];
    *c++ = t[2];
    *c++ = -1;
  }
  coordIndex.finishEditing();
}

void setPanelFields(const UnsewnGarment& cut, SoMFVec2f& panelPoints, SoMFInt32& seams) {
  panelPoints.setNum(static_cast<int>(cut.flat.size()));
  SbVec2f* uv = panelPoints.startEditing();
  for (const Vec2& p : cut.flat) *uv++ = SbVec2f(float(p.x()), float(p.y()));
  panelPoints.finishEditing();
  seams.setNum(static_cast<int>(2 * cut.seams.size()));
  int32_t* pair = seams.startEditing();
  for (const auto& [a, b] : cut.seams) *pair++ = a, *pair++ = b;
  seams.finishEditing();
  // Outputs, not settings: left out of written files.
  panelPoints.setDefault(TRUE);
  seams.setDefault(TRUE);
}

void clearPanelFields(SoMFVec2f& panelPoints, SoMFInt32& seams) {
  panelPoints.setNum(0);
  seams.setNum(0);
  panelPoints.setDefault(TRUE);
  seams.setDefault(TRUE);
}

}  // namespace figment

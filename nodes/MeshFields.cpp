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

}  // namespace figment

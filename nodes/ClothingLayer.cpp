#include "nodes/ClothingLayer.h"

#include "nodes/FacetOrder.h"
#include "nodes/GLStencilElement.h"

#include <Inventor/SbViewVolume.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/bundles/SoMaterialBundle.h>
#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/elements/SoDepthBufferElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoShapeHintsElement.h>
#include <Inventor/elements/SoViewVolumeElement.h>
#include <Inventor/elements/SoViewingMatrixElement.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoVertexProperty.h>

#include <GL/gl.h>

#include <vector>

SO_NODE_SOURCE(ClothingLayer);

void ClothingLayer::initClass() {
  if (classTypeId != SoType::badType()) return;
  GLStencilElement::initClass();
  SO_NODE_INIT_CLASS(ClothingLayer, SoIndexedFaceSet, "IndexedFaceSet");
}

ClothingLayer::ClothingLayer() {
  SO_NODE_CONSTRUCTOR(ClothingLayer);
  SO_NODE_ADD_FIELD(masked, (FALSE));
}

ClothingLayer::~ClothingLayer() = default;

namespace {

figment::ViewPoint viewPoint(SoState* state) {
  const SbViewVolume& volume = SoViewVolumeElement::get(state);
  const SbMatrix& model = SoModelMatrixElement::get(state);
  const SbMatrix toObject = model.inverse();
  figment::ViewPoint view;
  view.perspective = volume.getProjectionType() == SbViewVolume::PERSPECTIVE;
  toObject.multVecMatrix(volume.getProjectionPoint(), view.eye);
  toObject.multDirMatrix(volume.getProjectionDirection(), view.direction);
  view.toCamera = model;
  view.toCamera.multRight(SoViewingMatrixElement::get(state));
  view.clockwise = SoShapeHintsElement::getVertexOrdering(state) == SoShapeHintsElement::CLOCKWISE;
  return view;
}

// Smooth normals (area weighted): cloth is a smooth surface; two-sided lighting turns
// them for the facets seen from behind.
std::vector<SbVec3f> vertexNormals(const SbVec3f* points, int count, const int32_t* index, int indexCount) {
  std::vector<SbVec3f> normals(count, SbVec3f(0, 0, 0));
  int start = 0;
  while (start < indexCount) {
    int end = start;
    bool valid = true;
    while (end < indexCount && index[end] >= 0) valid &= index[end] < count, ++end;
    for (int k = start + 1; valid && k + 1 < end; ++k) {
      const SbVec3f n = (points[index[k]] - points[index[start]]).cross(points[index[k + 1]] - points[index[start]]);
      for (int corner : {index[start], index[k], index[k + 1]}) normals[corner] += n;
    }
    start = end + 1;
  }
  for (SbVec3f& n : normals)
    if (n.sqrLength() > 0.0f) n.normalize();
  return normals;
}

}  // namespace

void ClothingLayer::GLRender(SoGLRenderAction* action) {
  if (!shouldGLRender(action)) return;
  SoState* state = action->getState();
  // The order depends on the view: no render cache may keep it.
  SoCacheElement::invalidate(state);
  state->push();
  if (auto* properties = static_cast<SoVertexProperty*>(vertexProperty.getValue())) properties->GLRender(action);
  const SoCoordinateElement* coordinates = SoCoordinateElement::getInstance(state);
  const int pointCount = coordinates->getNum();
  std::vector<SbVec3f> points(pointCount);
  for (int i = 0; i < pointCount; ++i) points[i] = coordinates->get3(i);
  const int32_t* index = coordIndex.getValues(0);
  const int indexCount = coordIndex.getNum();
  const std::vector<figment::OrderedFacet> facets =
      figment::orderFacets(points.data(), pointCount, index, indexCount, viewPoint(state));
  const std::vector<SbVec3f> normals = vertexNormals(points.data(), pointCount, index, indexCount);

  SoMaterialBundle material(action);
  material.sendFirst();
  SbBool depthTest, depthWrite;
  SoDepthBufferElement::DepthWriteFunction usualTest;
  SbVec2f depthRange;
  SoDepthBufferElement::get(state, depthTest, depthWrite, usualTest, depthRange);
  bool drawingOver = false;
  bool open = false;
  for (const figment::OrderedFacet& facet : facets) {
    if (!open || facet.facesViewer != drawingOver) {
      if (open) glEnd();
      drawingOver = facet.facesViewer;
      // Facing the viewer: over everything drawn before (depth test ALWAYS, depth still
      // written); facing away: the usual depth test. A masked layer keeps off the
      // stencil's marks where it draws over.
      SoDepthBufferElement::set(state, TRUE, TRUE, drawingOver ? SoDepthBufferElement::ALWAYS : usualTest,
                                depthRange);
      if (masked.getValue()) GLStencilElement::set(state, drawingOver ? GLStencilElement::MASK : GLStencilElement::OFF);
      glBegin(GL_TRIANGLES);
      open = true;
    }
    for (int k = 1; k + 1 < facet.corners; ++k)
      for (int corner : {index[facet.firstIndex], index[facet.firstIndex + k], index[facet.firstIndex + k + 1]}) {
        glNormal3fv(normals[corner].getValue());
        glVertex3fv(points[corner].getValue());
      }
  }
  if (open) glEnd();
  state->pop();
}

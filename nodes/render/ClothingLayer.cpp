#include "nodes/render/ClothingLayer.h"

#include "nodes/render/FacetOrder.h"
#include "nodes/render/GLStencilElement.h"

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

struct ClothingLayer::DrawCache {
  // The geometry, kept while the coordinates and the layer's fields stay the same.
  SbUniqueId coordinatesId = 0, layerId = 0;
  std::vector<SbVec3f> points, smooth;  // coordinates and smooth normals
  std::vector<figment::FacetGeometry> facets;
  // The view the arrays were built for.
  bool built = false;
  SbMatrix toCamera;
  SbVec3f eye, direction;
  bool perspective = false, clockwise = false;
  // Triangle corners, three floats each: the facets facing away, then those facing
  // the viewer, each group far to near.
  std::vector<float> positions, normals;
  int awayCorners = 0, facingCorners = 0;

  bool sameView(const figment::ViewPoint& view) const {
    return built && view.toCamera == toCamera && view.eye == eye && view.direction == direction &&
           view.perspective == perspective && view.clockwise == clockwise;
  }
};

void ClothingLayer::GLRender(SoGLRenderAction* action) {
  if (!shouldGLRender(action)) return;
  SoState* state = action->getState();
  // The order depends on the view: no render cache may keep it.
  SoCacheElement::invalidate(state);
  state->push();
  if (auto* properties = static_cast<SoVertexProperty*>(vertexProperty.getValue())) properties->GLRender(action);
  const SoCoordinateElement* coordinates = SoCoordinateElement::getInstance(state);
  const figment::ViewPoint view = viewPoint(state);
  if (!cache_) cache_ = std::make_unique<DrawCache>();
  DrawCache& c = *cache_;
  const int32_t* index = coordIndex.getValues(0);
  const int indexCount = coordIndex.getNum();
  if (coordinates->getNodeId() != c.coordinatesId || getNodeId() != c.layerId) {
    const int pointCount = coordinates->getNum();
    c.points.resize(pointCount);
    for (int i = 0; i < pointCount; ++i) c.points[i] = coordinates->get3(i);
    c.smooth = vertexNormals(c.points.data(), pointCount, index, indexCount);
    c.facets = figment::describeFacets(c.points.data(), pointCount, index, indexCount);
    c.coordinatesId = coordinates->getNodeId();
    c.layerId = getNodeId();
    c.built = false;
  }
  if (!c.sameView(view)) {
    c.positions.clear(), c.normals.clear();
    const std::vector<figment::OrderedFacet> facets = figment::orderFacets(c.facets, view);
    for (bool facing : {false, true}) {
      const size_t before = c.positions.size();
      for (const figment::OrderedFacet& facet : facets) {
        if (facet.facesViewer != facing) continue;
        for (int k = 1; k + 1 < facet.corners; ++k)
          for (int corner : {index[facet.firstIndex], index[facet.firstIndex + k], index[facet.firstIndex + k + 1]}) {
            c.positions.insert(c.positions.end(), c.points[corner].getValue(), c.points[corner].getValue() + 3);
            c.normals.insert(c.normals.end(), c.smooth[corner].getValue(), c.smooth[corner].getValue() + 3);
          }
      }
      (facing ? c.facingCorners : c.awayCorners) = static_cast<int>((c.positions.size() - before) / 3);
    }
    c.toCamera = view.toCamera, c.eye = view.eye, c.direction = view.direction;
    c.perspective = view.perspective, c.clockwise = view.clockwise;
    c.built = true;
  }

  SoMaterialBundle material(action);
  material.sendFirst();
  SbBool depthTest, depthWrite;
  SoDepthBufferElement::DepthWriteFunction usualTest;
  SbVec2f depthRange;
  SoDepthBufferElement::get(state, depthTest, depthWrite, usualTest, depthRange);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, cache_->positions.data());
  glNormalPointer(GL_FLOAT, 0, cache_->normals.data());
  auto depth = [&](SoDepthBufferElement::DepthWriteFunction function) {
    SoDepthBufferElement::set(state, TRUE, TRUE, function, depthRange);
  };
  const int away = cache_->awayCorners, facing = cache_->facingCorners;
  // Three draws, each one state change, not one per change of facing along the depth
  // order (hundreds on a draped garment, and each costs a pipeline flush):
  // 1. facets facing away, with the usual depth test, marking the layer bit where they
  //    show;
  if (away > 0) {
    depth(usualTest);
    GLStencilElement::set(state, GLStencilElement::MARK_LAYER);
    glDrawArrays(GL_TRIANGLES, 0, away);
  }
  // 2. facets facing the viewer, far to near, over everything drawn before them (depth
  //    test ALWAYS, depth written), except where a facet of this layer facing away
  //    shows (and, when masked, where a body part marked the stencil);
  if (facing > 0) {
    depth(SoDepthBufferElement::ALWAYS);
    GLStencilElement::set(state, masked.getValue() ? GLStencilElement::OUTSIDE_LAYER_AND_PARTS
                                                   : GLStencilElement::OUTSIDE_LAYER);
    glDrawArrays(GL_TRIANGLES, away, facing);
  }
  // 3. there, the layer's own facets meet: the depth test decides between them, as it
  //    would have in a single far-to-near pass for cloth that does not cross itself.
  if (facing > 0 && away > 0) {
    depth(usualTest);
    GLStencilElement::set(state, GLStencilElement::INSIDE_LAYER);
    glDrawArrays(GL_TRIANGLES, away, facing);
  }
  if (away > 0) GLStencilElement::clearLayerBit();
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  state->pop();
}

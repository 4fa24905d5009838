#include "nodes/render/ClothingLayer.h"

#include <GL/gl.h>
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

#include <vector>

#include "guard/CoordIndexFaces.h"
#include "nodes/render/FacetOrder.h"
#include "nodes/render/GLStencilElement.h"
#include "nodes/render/StencilDecisionElement.h"
#include "nodes/render/StencilRule.h"
#include "nodes/render/StencilRuleElement.h"

SO_NODE_SOURCE(ClothingLayer);

void ClothingLayer::initClass() {
  if (classTypeId != SoType::badType()) return;
  GLStencilElement::initClass();
  StencilRuleElement::initClass();
  StencilDecisionElement::initClass();
  SO_NODE_INIT_CLASS(ClothingLayer, SoIndexedFaceSet, "IndexedFaceSet");
}

ClothingLayer::ClothingLayer() {
  SO_NODE_CONSTRUCTOR(ClothingLayer);
  SO_NODE_ADD_FIELD(masked, (FALSE));
  SO_NODE_ADD_FIELD(stencilRule, (TRUE));
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
  for (const figment::guard::CoordIndexFace& face : figment::guard::coordIndexFaces(index, indexCount)) {
    if (!figment::guard::cornersBelow(face, index, count)) continue;
    const int start = face.first;
    for (int k = start + 1; k + 1 < face.end; ++k) {
      const SbVec3f n = (points[index[k]] - points[index[start]]).cross(points[index[k + 1]] - points[index[start]]);
      for (int corner : {index[start], index[k], index[k + 1]}) normals[corner] += n;
    }
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
  figment::Winding winding = figment::Winding::UNDECIDED;  // which side is the outside
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

  // Takes the coordinates, smooth normals and facets, when they changed.
  void takeGeometry(const SoCoordinateElement* coordinates, const ClothingLayer& layer) {
    if (coordinates->getNodeId() == coordinatesId && layer.getNodeId() == layerId) return;
    const int32_t* index = layer.coordIndex.getValues(0);
    const int indexCount = layer.coordIndex.getNum();
    const int pointCount = coordinates->getNum();
    points.resize(pointCount);
    for (int i = 0; i < pointCount; ++i) points[i] = coordinates->get3(i);
    smooth = vertexNormals(points.data(), pointCount, index, indexCount);
    facets = figment::describeFacets(points.data(), pointCount, index, indexCount);
    winding = figment::outsideWinding(facets);
    coordinatesId = coordinates->getNodeId();
    layerId = layer.getNodeId();
    built = false;
  }

  // Classifies each facet as facing the viewer or away and sorts them far to near
  // (figment::orderFacets), then lays out the arrays: away, then facing.
  void arrangeForView(const figment::ViewPoint& view, const int32_t* index) {
    if (sameView(view)) return;
    positions.clear(), normals.clear();
    const std::vector<figment::OrderedFacet> ordered = figment::orderFacets(facets, view);
    for (bool facing : {false, true}) {
      const size_t before = positions.size();
      for (const figment::OrderedFacet& facet : ordered)
        if (facet.facesViewer == facing) addTriangles(facet, index);
      (facing ? facingCorners : awayCorners) = static_cast<int>((positions.size() - before) / 3);
    }
    toCamera = view.toCamera, eye = view.eye, direction = view.direction;
    perspective = view.perspective, clockwise = view.clockwise;
    built = true;
  }

  // The facet's triangles, corner by corner: a fan from its first corner, but a quad
  // split along its second diagonal (corners 0 1 3 and 1 2 3), as OpenGL splits the
  // GL_QUADS Coin draws an IndexedFaceSet's quads with (Mesa, last provoking vertex):
  // a bent quad then covers the very pixels it covers in the depth buffer's picture.
  void addTriangles(const figment::OrderedFacet& facet, const int32_t* index) {
    const int32_t* corners = index + facet.firstIndex;
    if (facet.corners == 4) {
      for (int corner : {corners[0], corners[1], corners[3], corners[1], corners[2], corners[3]}) addCorner(corner);
      return;
    }
    for (int k = 1; k + 1 < facet.corners; ++k)
      for (int corner : {corners[0], corners[k], corners[k + 1]}) addCorner(corner);
  }

  void addCorner(int corner) {
    positions.insert(positions.end(), points[corner].getValue(), points[corner].getValue() + 3);
    normals.insert(normals.end(), smooth[corner].getValue(), smooth[corner].getValue() + 3);
  }
};

bool ClothingLayer::maskedNow(SoGLRenderAction* action) {
  if (!stencilRule.getValue() || !StencilRuleElement::get(action->getState())) return masked.getValue();
  return figment::decideStencil(action).masks(this);
}

void ClothingLayer::GLRender(SoGLRenderAction* action) {
  if (!shouldGLRender(action)) return;
  SoState* state = action->getState();
  // The order depends on the view: no render cache may keep it.
  SoCacheElement::invalidate(state);
  GLStencilElement::clearEachFrame(action);
  const bool maskedByParts = maskedNow(action);
  state->push();
  if (auto* properties = static_cast<SoVertexProperty*>(vertexProperty.getValue())) properties->GLRender(action);
  if (!cache_) cache_ = std::make_unique<DrawCache>();
  cache_->takeGeometry(SoCoordinateElement::getInstance(state), *this);
  figment::ViewPoint view = viewPoint(state);
  // The garment's own shape says which side is its outside, whatever the ShapeHints
  // say; the hints decide for a sheet whose shape cannot tell.
  if (cache_->winding != figment::Winding::UNDECIDED) view.clockwise = cache_->winding == figment::Winding::CLOCKWISE;
  cache_->arrangeForView(view, coordIndex.getValues(0));
  SoMaterialBundle material(action);
  material.sendFirst();
  drawArranged(state, maskedByParts);
  state->pop();
}

// Three or four draws, each one state change, not one per change of facing along the depth
// order (hundreds on a draped garment, and each costs a pipeline flush).
void ClothingLayer::drawArranged(SoState* state, bool maskedByParts) {
  SbBool depthTest, depthWrite;
  SoDepthBufferElement::DepthWriteFunction usualTest;
  SbVec2f depthRange;
  SoDepthBufferElement::get(state, depthTest, depthWrite, usualTest, depthRange);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, cache_->positions.data());
  glNormalPointer(GL_FLOAT, 0, cache_->normals.data());
  auto draw = [&](SoDepthBufferElement::DepthWriteFunction test, GLStencilElement::Mode stencil, int first, int count) {
    SoDepthBufferElement::set(state, TRUE, TRUE, test, depthRange);
    GLStencilElement::set(state, stencil);
    glDrawArrays(GL_TRIANGLES, first, count);
  };
  const int away = cache_->awayCorners, facing = cache_->facingCorners;
  // 1. Depth-tested: facets facing away, with the usual depth test, marking the layer
  //    bit where they show.
  if (away > 0) draw(usualTest, GLStencilElement::MARK_LAYER, 0, away);
  // 2. Over: facets facing the viewer, far to near, over everything drawn before them
  //    (depth test ALWAYS, depth written), except where a facet of this layer facing
  //    away shows (and, when masked, where a body part marked the stencil).
  if (facing > 0)
    draw(SoDepthBufferElement::ALWAYS,
         maskedByParts ? GLStencilElement::OUTSIDE_LAYER_AND_PARTS : GLStencilElement::OUTSIDE_LAYER, away, facing);
  // 3. Where the layer meets itself: there the depth test decides between its own
  //    facets, as it would have in a single far-to-near pass for cloth that does not
  //    cross itself.
  if (facing > 0 && away > 0) draw(usualTest, GLStencilElement::INSIDE_LAYER, away, facing);
  // 4. Where a body part marked the stencil (masked only): the depth test decides
  //    between the part and the facets facing the viewer, so the part stays in front
  //    where it is in front and cloth in front of it is never cut away (a strap across
  //    the upper arm lost its outer edge to the arm's mark, in notches).
  if (facing > 0 && maskedByParts) draw(usualTest, GLStencilElement::ON_PARTS_OUTSIDE_LAYER, away, facing);
  if (away > 0) GLStencilElement::clearLayerBit();
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

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

#include <algorithm>
#include <vector>

#include "guard/CoordIndexFaces.h"
#include "nodes/NodeSource.h"
#include "nodes/render/FacetOrder.h"
#include "nodes/render/GLStencilElement.h"
#include "nodes/render/StencilDecisionElement.h"
#include "nodes/render/StencilRule.h"
#include "nodes/render/StencilRuleElement.h"
#include "sim/core/DisplaySubdivision.h"

FIGMENT_NODE_SOURCE_AFTER(ClothingLayer, SoIndexedFaceSet, "IndexedFaceSet", initStencilElements)

ClothingLayer::ClothingLayer() {
  SO_NODE_CONSTRUCTOR(ClothingLayer);
  SO_NODE_ADD_FIELD(masked, (FALSE));
  SO_NODE_ADD_FIELD(stencilRule, (TRUE));
  SO_NODE_ADD_FIELD(displaySubdivision, (0));
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

// The triangles GL draws for the faces of `index`: a quad split along its second diagonal
// (see DrawCache::addTriangles), any other face fanned from its first corner.
std::vector<figment::Triangle> drawnTriangles(const int32_t* index, int indexCount, int pointCount) {
  std::vector<figment::Triangle> triangles;
  for (const figment::guard::CoordIndexFace& face : figment::guard::coordIndexFaces(index, indexCount)) {
    if (face.corners() < 3 || !figment::guard::cornersBelow(face, index, pointCount)) continue;
    const int32_t* c = index + face.first;
    if (face.corners() == 4) {
      triangles.push_back({c[0], c[1], c[3]});
      triangles.push_back({c[1], c[2], c[3]});
      continue;
    }
    for (int k = 1; k + 1 < face.corners(); ++k) triangles.push_back({c[0], c[k], c[k + 1]});
  }
  return triangles;
}

}  // namespace

struct ClothingLayer::DrawCache {
  // The geometry, kept while the coordinates and the layer's fields stay the same.
  SbUniqueId coordinatesId = 0, layerId = 0;
  // The display mesh: its points, smooth normals and faces (the layer's coordIndex itself
  // without subdivision), and the layout that makes it, kept while the faces stay.
  std::vector<SbVec3f> points, smooth;
  std::vector<int32_t> index;
  std::unique_ptr<figment::DisplaySubdivision> layout;
  SbUniqueId layoutLayerId = 0;
  // The box of the display mesh's triangles (empty without subdivision): what the layer
  // draws reaches this far past its faces (computeBBox).
  SbBox3f drawnBox;
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

  // Takes the coordinates, makes the display mesh and its facets, when they changed.
  void takeGeometry(const SoCoordinateElement* coordinates, const ClothingLayer& layer) {
    if (coordinates->getNodeId() == coordinatesId && layer.getNodeId() == layerId) return;
    const int32_t* faces = layer.coordIndex.getValues(0);
    const int indexCount = layer.coordIndex.getNum();
    const int pointCount = coordinates->getNum();
    points.resize(pointCount);
    for (int i = 0; i < pointCount; ++i) points[i] = coordinates->get3(i);
    const int levels = std::clamp(layer.displaySubdivision.getValue(), 0, kMostDisplaySubdivision);
    if (levels == 0) {
      layout.reset();
      index.assign(faces, faces + indexCount);
      smooth = vertexNormals(points.data(), pointCount, faces, indexCount);
      drawnBox.makeEmpty();
    } else {
      subdivide(layer, levels);
      drawnBox.makeEmpty();
      for (int32_t corner : index)
        if (corner >= 0) drawnBox.extendBy(points[corner]);
    }
    facets = figment::describeFacets(points.data(), static_cast<int>(points.size()), index.data(),
                                     static_cast<int>(index.size()));
    winding = figment::outsideWinding(facets);
    coordinatesId = coordinates->getNodeId();
    layerId = layer.getNodeId();
    built = false;
  }

  // Replaces `points` (the coordinates) with the display mesh's `levels` splits of the
  // faces GL draws, and fills `smooth` and `index` with its normals and triangles.
  void subdivide(const ClothingLayer& layer, int levels) {
    std::vector<figment::Vec3> coarse(points.size());
    for (size_t i = 0; i < points.size(); ++i) coarse[i] = figment::Vec3(points[i][0], points[i][1], points[i][2]);
    if (!layout || layoutLayerId != layer.getNodeId() || layout->levels() != levels ||
        layout->vertexCount() != static_cast<int>(coarse.size())) {
      const int pointCount = static_cast<int>(coarse.size());
      layout = std::make_unique<figment::DisplaySubdivision>(
          drawnTriangles(layer.coordIndex.getValues(0), layer.coordIndex.getNum(), pointCount), coarse, levels);
      layoutLayerId = layer.getNodeId();
    }
    std::vector<figment::Vec3> fine, fineNormals;
    layout->apply(coarse, fine, fineNormals);
    points.resize(fine.size()), smooth.resize(fine.size());
    for (size_t i = 0; i < fine.size(); ++i) {
      points[i].setValue(float(fine[i].x()), float(fine[i].y()), float(fine[i].z()));
      smooth[i].setValue(float(fineNormals[i].x()), float(fineNormals[i].y()), float(fineNormals[i].z()));
    }
    index.clear();
    for (const figment::Triangle& t : layout->triangles()) index.insert(index.end(), {t[0], t[1], t[2], -1});
  }

  // Classifies each facet as facing the viewer or away and sorts them far to near
  // (figment::orderFacets), then lays out the arrays: away, then facing.
  void arrangeForView(const figment::ViewPoint& view) {
    if (sameView(view)) return;
    positions.clear(), normals.clear();
    const std::vector<figment::OrderedFacet> ordered = figment::orderFacets(facets, view);
    for (bool facing : {false, true}) {
      const size_t before = positions.size();
      for (const figment::OrderedFacet& facet : ordered)
        if (facet.facesViewer == facing) addTriangles(facet);
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
  void addTriangles(const figment::OrderedFacet& facet) {
    const int32_t* corners = index.data() + facet.firstIndex;
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
  arrange(action);
  SoMaterialBundle material(action);
  material.sendFirst();
  drawArranged(state, maskedByParts);
  state->pop();
}

void ClothingLayer::GLRenderPlain(SoGLRenderAction* action) {
  if (!shouldGLRender(action)) return;
  SoState* state = action->getState();
  SoCacheElement::invalidate(state);
  state->push();
  arrange(action);
  SoMaterialBundle material(action);
  material.sendFirst();
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, cache_->positions.data());
  glNormalPointer(GL_FLOAT, 0, cache_->normals.data());
  glDrawArrays(GL_TRIANGLES, 0, cache_->awayCorners + cache_->facingCorners);
  glDisableClientState(GL_NORMAL_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
  state->pop();
}

void ClothingLayer::computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) {
  inherited::computeBBox(action, box, center);
  if (box.isEmpty() || std::clamp(displaySubdivision.getValue(), 0, kMostDisplaySubdivision) == 0) return;
  // The display mesh, made here as the next render would make it (and kept for it).
  SoState* state = action->getState();
  state->push();
  if (auto* properties = static_cast<SoVertexProperty*>(vertexProperty.getValue())) properties->doAction(action);
  if (!cache_) cache_ = std::make_unique<DrawCache>();
  cache_->takeGeometry(SoCoordinateElement::getInstance(state), *this);
  state->pop();
  box.extendBy(cache_->drawnBox);
  center = box.getCenter();
}

void ClothingLayer::arrange(SoGLRenderAction* action) {
  SoState* state = action->getState();
  if (auto* properties = static_cast<SoVertexProperty*>(vertexProperty.getValue())) properties->GLRender(action);
  if (!cache_) cache_ = std::make_unique<DrawCache>();
  cache_->takeGeometry(SoCoordinateElement::getInstance(state), *this);
  figment::ViewPoint view = viewPoint(state);
  // The garment's own shape says which side is its outside, whatever the ShapeHints
  // say; the hints decide for a sheet whose shape cannot tell.
  if (cache_->winding != figment::Winding::UNDECIDED) view.clockwise = cache_->winding == figment::Winding::CLOCKWISE;
  cache_->arrangeForView(view);
}

std::string ClothingLayer::fieldProblem() const {
  const int levels = displaySubdivision.getValue();
  if (levels >= 0 && levels <= kMostDisplaySubdivision) return "";
  const SbName name = getName();
  return std::string("ClothingLayer") + (name.getLength() > 0 ? std::string(" '") + name.getString() + "'" : "") +
         ": displaySubdivision = " + std::to_string(levels) + " is not 0 to " + std::to_string(kMostDisplaySubdivision);
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

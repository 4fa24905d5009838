#pragma once
// ClothingLayer: one layer of clothing, an indexed face set (paper §5).

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>

#include <memory>

/*!
  \class ClothingLayer nodes/render/ClothingLayer.h
  \brief The faces of one cloth mesh; replaces an IndexedFaceSet one for one.

  Paper §5: a Clothing Layer keeps the definition of an indexed face set, so any
  IndexedFaceSet in a scene can be swapped for one, and adds how the layer is drawn
  over what lies beneath it. It accepts every IndexedFaceSet field, and picks, bounds,
  counts and writes exactly as an IndexedFaceSet does.

  Drawing (the hybrid depth-buffer / depth-sort method of §5): every render, each facet
  is tested against the line from the eye (or the viewing direction of an orthographic
  camera) to its centre. Facets whose front faces the viewer (or is nearly edge-on to
  the line of sight: the paper draws as usual only those facing "substantially" away)
  are taken to enclose
  whatever was drawn before them on that line of sight, the body or an inner layer:
  they are drawn with the depth test ALWAYS and depth writes on, so skin that pokes a
  few millimetres through the cloth stays hidden. Facets facing away (the inside of the
  garment, seen through a neckline or under a hem) use the usual depth test. All facets
  are drawn far to near by their centres, so folds of the same mesh cover each other
  rightly. The front of a facet is the garment's outside, found from the layer's shape
  (figment::outsideWinding: the side facing away from the garment's middle), whatever
  the winding of its faces: a garment wound clockwise is drawn as the same garment
  wound counter-clockwise (its inside, seen under a hem, keeps the depth test). Only a
  sheet too flat to tell takes the ShapeHints' ordering: counter-clockwise unless it
  says CLOCKWISE.
  When the layer is masked, the facets drawn over are kept off the pixels that a
  StencilSeparator marked (paper §5: a forearm in front of a shirt). With `stencilRule`
  TRUE (the default) the stencil rule (figment::decideStencil, nodes/render/StencilRule.h)
  decides at each render, for the view being rendered: the layer is masked when a
  StencilSeparator lies in front of it. The answer is render state, not a field. With
  `stencilRule` FALSE, or in a render that keeps the scene's fields
  (figment::keepStencilFields, figment-view --keep-stencil-fields), `masked` decides.

  What the drawing uses: the coordinates (Coordinate3 or vertexProperty), coordIndex
  (polygons fan-triangulated), the first material (overall binding) and smooth normals
  computed from the facets; explicit normals, per-face materials and textures are
  ignored when drawing. Because the order depends on the view, a ClothingLayer keeps
  any separator above it from caching its rendering.

  The garment's coordinates come from the Coordinate3 before it, usually connected to
  a ClothEngine's output:
  \code
    Coordinate3 { point = DEF Drape ClothEngine { ... } . positions }
    ClothingLayer { coordIndex = USE Pattern.coordIndex }
  \endcode

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    ClothingLayer {
        vertexProperty NULL
        coordIndex 0
        materialIndex -1
        normalIndex -1
        textureCoordIndex -1
        masked FALSE
        stencilRule TRUE
    }
  \endcode
*/
class ClothingLayer : public SoIndexedFaceSet {
  typedef SoIndexedFaceSet inherited;
  SO_NODE_HEADER(ClothingLayer);

 public:
  static void initClass();
  ClothingLayer();

  // Whether the facets that face the viewer are masked by the stencil buffer, so body
  // parts drawn into it by a StencilSeparator stay in front (paper §5), when
  // `stencilRule` is FALSE or the render keeps the scene's fields. Default FALSE.
  SoSFBool masked;
  // Whether the stencil rule decides, per view, in place of `masked`. Default TRUE.
  SoSFBool stencilRule;

  void GLRender(SoGLRenderAction* action) override;

 protected:
  ~ClothingLayer() override;

 private:
  // The facets in drawing order, as vertex arrays, kept while neither the view nor the
  // geometry changes (a still camera re-draws without sorting again).
  struct DrawCache;
  std::unique_ptr<DrawCache> cache_;

  // Whether this render masks the layer: the rule's answer or `masked`.
  bool maskedNow(SoGLRenderAction* action);
  // The three draws of the arranged facets (see the class comment).
  void drawArranged(SoState* state, bool maskedByParts);
};

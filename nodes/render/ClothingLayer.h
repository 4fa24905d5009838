#pragma once
// ClothingLayer: one layer of clothing, an indexed face set (paper §5).

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>

#include <memory>
#include <string>

/*!
  \class ClothingLayer nodes/render/ClothingLayer.h
  \brief The faces of one cloth mesh; replaces an IndexedFaceSet one for one.

  Paper §5: a Clothing Layer keeps the definition of an indexed face set, so any
  IndexedFaceSet in a scene can be swapped for one, and adds how the layer is drawn
  over what lies beneath it. It accepts every IndexedFaceSet field, and picks, counts
  and writes exactly as an IndexedFaceSet does; it bounds as one too, but for the display
  mesh (below), whose box it adds.

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
  ignored when drawing.

  The display mesh: with `displaySubdivision` N > 0 the layer draws, in place of its
  faces, a finer mesh made from them at each change of the coordinates
  (figment::DisplaySubdivision, sim/core/DisplaySubdivision.h): each face triangulated as
  GL draws it, each triangle split in four N times, the new vertices on a smooth surface
  through the old (which stay where the drape put them), hems, sleeve ends and necklines
  smoothed along their curves, and normals averaged over vertices at the same position
  (across a seam). The simulation stays as coarse as the drape needs; the picture shows it
  smooth. Every pass of the hybrid drawing (the sort, the facing test, the stencil) uses
  the display mesh, and so does the depth buffer alone (GLRenderPlain: figment-view
  --depth-buffer-only). The bounding box covers what is drawn: the faces' box, grown to
  hold the display mesh (which reaches a little past them), made with it and kept with
  it while the coordinates stay. Picking, counts, writing and --export keep the faces.
  Because the order depends on the view, a ClothingLayer keeps any separator above it
  from caching its rendering.

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
        displaySubdivision 0
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
  // How many times the display mesh splits each triangle in four (see above), 0 to
  // kMostDisplaySubdivision. Default 0: the faces as the simulation made them, as the
  // paper draws them (its figures, and the -plain twins of the hybrid scenes, stay pixel
  // for pixel what they were); 1 draws four triangles for each, 2 sixteen.
  SoSFInt32 displaySubdivision;
  static constexpr int kMostDisplaySubdivision = 3;

  void GLRender(SoGLRenderAction* action) override;
  // The display mesh as the depth buffer alone draws it: the scene's depth test, no
  // sorting, no stencil (the stand-in of figment-view --depth-buffer-only for a layer with
  // a display mesh, which a plain IndexedFaceSet could not draw).
  void GLRenderPlain(SoGLRenderAction* action);
  // "" when the fields may be drawn, else one line naming the layer, the field and the
  // value ("ClothingLayer 'Dress': displaySubdivision = 7 is not 0 to 3").
  std::string fieldProblem() const;

 protected:
  ~ClothingLayer() override;
  // The box of what the layer draws: its faces, and with a display mesh that mesh too,
  // which stands a little past them (the default dress's by up to 2 mm). A camera framed
  // on the scene (viewAll), culling and the near and far planes then hold all of it.
  void computeBBox(SoAction* action, SbBox3f& box, SbVec3f& center) override;

 private:
  // The facets in drawing order, as vertex arrays, kept while neither the view nor the
  // geometry changes (a still camera re-draws without sorting again).
  struct DrawCache;
  std::unique_ptr<DrawCache> cache_;

  // Whether this render masks the layer: the rule's answer or `masked`.
  bool maskedNow(SoGLRenderAction* action);
  // Takes the coordinates and the view, and arranges the display mesh's facets for it.
  void arrange(SoGLRenderAction* action);
  // The three draws of the arranged facets (see the class comment).
  void drawArranged(SoState* state, bool maskedByParts);
};

#pragma once
// ClothingLayer: one layer of clothing, an indexed face set (paper §5).

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>

/*!
  \class ClothingLayer nodes/ClothingLayer.h
  \brief The faces of one cloth mesh; replaces an IndexedFaceSet one for one.

  Paper §5: a Clothing Layer keeps the definition of an indexed face set, so any
  IndexedFaceSet in a scene can be swapped for one, and adds how the layer is drawn
  over what lies beneath it. It accepts every IndexedFaceSet field (coordIndex,
  normalIndex, materialIndex, textureCoordIndex, vertexProperty) and today draws,
  picks and counts exactly as an IndexedFaceSet does; the hybrid depth-buffer /
  depth-sort drawing of §5 comes in a later change.

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
  // parts drawn into it by a StencilSeparator stay in front (paper §5). Default FALSE.
  SoSFBool masked;

 protected:
  ~ClothingLayer() override;
};

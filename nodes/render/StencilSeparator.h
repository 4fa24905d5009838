#pragma once
// StencilSeparator: a separator whose children also mark the stencil buffer (paper §5).

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/nodes/SoSeparator.h>

/*!
  \class StencilSeparator nodes/render/StencilSeparator.h
  \brief A Separator that can make its children mark the pixels they draw.

  Paper §5: body parts drawn before the clothing, but in front of it for this view (a
  forearm across a shirt), would be painted over by a ClothingLayer's facets that face
  the viewer. When this separator writes the stencil, its children also mark their
  pixels in the stencil buffer, and a masked ClothingLayer keeps off them.

  Which parts write and which layers are masked depends on the viewpoint. With
  `stencilRule` TRUE (the default) the separator asks the stencil rule
  (figment::decideStencil, nodes/render/StencilRule.h) at each render, for the view
  being rendered: it writes when it lies in front of a ClothingLayer. The answer is
  render state: no field changes, so an interactive viewer is not asked to redraw. With
  `stencilRule` FALSE, or in a render that keeps the scene's fields
  (figment::keepStencilFields, figment-view --keep-stencil-fields), `writeStencil`
  decides, as the paper's boolean field. In every other action it is a Separator.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    StencilSeparator {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        writeStencil FALSE
        stencilRule TRUE
    }
  \endcode
*/
class StencilSeparator : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(StencilSeparator);

 public:
  static void initClass();
  StencilSeparator();

  // Whether the children mark the pixels they draw in the stencil buffer, when
  // `stencilRule` is FALSE or the render keeps the scene's fields. Default FALSE.
  SoSFBool writeStencil;
  // Whether the stencil rule decides, per view, in place of `writeStencil`. Default TRUE.
  SoSFBool stencilRule;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;

 protected:
  ~StencilSeparator() override;

 private:
  // Renders as a Separator does (along a path or below it), marking the stencil when
  // writesStencil().
  void renderMarking(SoGLRenderAction* action, bool inPath);
  // Whether this render marks the stencil: the rule's answer or `writeStencil`.
  bool writesStencil(SoGLRenderAction* action);
};

#pragma once
// StencilSeparator: a separator whose children also mark the stencil buffer (paper §5).

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/nodes/SoSeparator.h>

/*!
  \class StencilSeparator nodes/render/StencilSeparator.h
  \brief A Separator that can make its children mark the pixels they draw.

  Paper §5: body parts drawn before the clothing, but in front of it for this view (a
  forearm across a shirt), would be painted over by a ClothingLayer's facets that face
  the viewer. With `writeStencil` TRUE the children of this separator also mark their
  pixels in the stencil buffer, and a ClothingLayer with `masked` TRUE keeps off them.
  Which parts write and which layers are masked depends on the viewpoint:
  figment::applyStencilRule() (nodes/render/StencilRule.h) sets both fields for a camera.
  In every other action it is a Separator.

  <b>FILE FORMAT/DEFAULTS:</b>
  \code
    StencilSeparator {
        renderCaching AUTO
        boundingBoxCaching AUTO
        renderCulling AUTO
        pickCulling AUTO
        writeStencil FALSE
    }
  \endcode
*/
class StencilSeparator : public SoSeparator {
  typedef SoSeparator inherited;
  SO_NODE_HEADER(StencilSeparator);

 public:
  static void initClass();
  StencilSeparator();

  // Whether the children mark the pixels they draw in the stencil buffer. Default FALSE.
  SoSFBool writeStencil;

  void GLRenderBelowPath(SoGLRenderAction* action) override;
  void GLRenderInPath(SoGLRenderAction* action) override;

 protected:
  ~StencilSeparator() override;

 private:
  // Renders as a Separator does (along a path or below it), marking the stencil when
  // writeStencil is TRUE.
  void renderMarking(SoGLRenderAction* action, bool inPath);
};

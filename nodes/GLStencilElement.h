#pragma once
// GLStencilElement: the stencil buffer's use, as Coin state, so a separator undoes it
// (Coin has depth and colour elements but none for the stencil).

#include <Inventor/elements/SoSubElement.h>

/*!
  \class GLStencilElement nodes/GLStencilElement.h
  \brief How drawing uses the stencil buffer now (paper §5's stencil mask).

  - OFF: no stencil test (the default).
  - WRITE: everything drawn also marks its pixels in the stencil buffer (StencilSeparator
    with writeStencil TRUE): a body part that must stay in front.
  - MASK: drawing skips marked pixels (a masked ClothingLayer, for its facets that ignore
    the depth buffer).
  Setting the element issues the GL calls; popping it restores the state below. Enabled
  for SoGLRenderAction only. The stencil must be cleared at the start of each frame:
  figment::clearStencilEachFrame() adds that to a render action.
*/
class GLStencilElement : public SoElement {
  typedef SoElement inherited;
  SO_ELEMENT_HEADER(GLStencilElement);

 public:
  enum Mode { OFF, WRITE, MASK };

  static void initClass();
  static void set(SoState* state, Mode mode);
  static Mode get(SoState* state);

  void init(SoState* state) override;
  void push(SoState* state) override;
  void pop(SoState* state, const SoElement* previousTop) override;
  SbBool matches(const SoElement* element) const override;
  SoElement* copyMatchInfo() const override;

 protected:
  ~GLStencilElement() override;

 private:
  void updateGL() const;
  Mode mode_ = OFF;
};

class SoGLRenderAction;

namespace figment {
// Adds a pre-render callback to `action` that clears the stencil buffer before each
// frame (SoOffscreenRenderer and viewers clear colour and depth only).
void clearStencilEachFrame(SoGLRenderAction& action);
}  // namespace figment

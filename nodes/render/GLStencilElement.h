#pragma once
// GLStencilElement: the stencil buffer's use, as Coin state, so a separator undoes it
// (Coin has depth and colour elements but none for the stencil).

#include <Inventor/elements/SoSubElement.h>

class SoGLRenderAction;

/*!
  \class GLStencilElement nodes/render/GLStencilElement.h
  \brief How drawing uses the stencil buffer now (paper §5's stencil mask).

  Two bits of the stencil buffer are used:
  - the body-part bit (1): set where a StencilSeparator with writeStencil TRUE draws (a
    body part that must stay in front); a masked ClothingLayer keeps off it;
  - the layer bit (2): set where a ClothingLayer's facets facing away from the viewer
    are visible, while that layer draws, and cleared after it (see ClothingLayer).
  Setting the element issues the GL calls; popping it restores the state below. Enabled
  for SoGLRenderAction only. The stencil is cleared at the start of each frame (a
  pre-render callback that clearEachFrame() adds to the render action the first time a
  StencilSeparator or ClothingLayer renders with it), so no application has to.
*/
class GLStencilElement : public SoElement {
  typedef SoElement inherited;
  SO_ELEMENT_HEADER(GLStencilElement);

 public:
  enum Mode {
    OFF,                      // no stencil test (the default)
    MARK_PART,                // set the body-part bit where drawn
    MARK_LAYER,               // set the layer bit where drawn
    OUTSIDE_LAYER,            // draw only where the layer bit is clear
    OUTSIDE_LAYER_AND_PARTS,  // ... and the body-part bit too (a masked layer)
    INSIDE_LAYER,             // draw only where the layer bit is set
    ON_PARTS_OUTSIDE_LAYER,   // draw only where the body-part bit is set and the layer bit clear
  };
  static constexpr unsigned kPartBit = 1, kLayerBit = 2;

  static void initClass();
  static void set(SoState* state, Mode mode);
  static Mode get(SoState* state);
  // Clears the layer bit everywhere (the body-part bit stays).
  static void clearLayerBit();
  // Makes sure `action` clears the stencil before every frame (SoOffscreenRenderer and
  // viewers clear colour and depth only): the first call for an action's state clears
  // it now, before anything used it this frame, and adds a pre-render callback for the
  // frames after. Later calls do nothing; a new state (Coin makes one when the set of
  // enabled elements changes) adds the callback again, which only clears twice.
  static void clearEachFrame(SoGLRenderAction* action);

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
  bool clearedEachFrame_ = false;  // bottom element only: the callback is in place
};

// Registers GLStencilElement, StencilRuleElement and StencilDecisionElement, in that order:
// what a node that draws through the stencil rule (ClothingLayer, StencilSeparator) needs
// registered before itself.
void initStencilElements();

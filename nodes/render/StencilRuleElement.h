#pragma once
// StencilRuleElement: whether the stencil rule decides, in this render, which
// StencilSeparators write the stencil and which ClothingLayers are masked.

#include <Inventor/elements/SoInt32Element.h>

class SoGLRenderAction;

/*!
  \class StencilRuleElement nodes/render/StencilRuleElement.h
  \brief On (the default): StencilSeparators and ClothingLayers whose `stencilRule` is
  TRUE follow the stencil rule (figment::decideStencil) for the view being rendered.
  Off: every one of them uses its own `writeStencil` / `masked` value, as written in
  the scene. Enabled for SoGLRenderAction only; figment::keepStencilFields() turns it
  off for a whole render.
*/
class StencilRuleElement : public SoInt32Element {
  typedef SoInt32Element inherited;
  SO_ELEMENT_HEADER(StencilRuleElement);

 public:
  static void initClass();
  void init(SoState* state) override;

  static void set(SoState* state, bool ruleDecides);
  static bool get(SoState* state);

 protected:
  ~StencilRuleElement() override;
};

namespace figment {
// While `keep` is true, every render `action` does uses the scene's own
// StencilSeparator.writeStencil and ClothingLayer.masked values: the stencil rule is
// off (figment-view --keep-stencil-fields, the paper's Figure 5.3a). A call with true
// adds a pre-render callback to the action; the matching call with false removes it.
void keepStencilFields(SoGLRenderAction& action, bool keep);
}  // namespace figment

#pragma once
// StencilDecisionElement: the stencil rule's last decision, kept in the render
// action's state so that each action (each session, each thread) has its own.

#include <Inventor/SbMatrix.h>
#include <Inventor/SbViewportRegion.h>
#include <Inventor/elements/SoSubElement.h>

#include <functional>

#include "nodes/render/StencilRule.h"

/*!
  \class StencilDecisionElement nodes/render/StencilDecisionElement.h
  \brief A cache, not traversal state: the decision figment::decideStencil(action)
  made for the scene, view and viewport it was made for. Enabled for SoGLRenderAction
  only; nothing pushes it, so the one instance at the bottom of an action's state lives
  as long as that state, and a still camera re-draws without deciding again. Two
  actions never share it (a function-static cache would be shared by every render in
  the process, and raced by two threads).
*/
class StencilDecisionElement : public SoElement {
  typedef SoElement inherited;
  SO_ELEMENT_HEADER(StencilDecisionElement);

 public:
  // What a decision was made for.
  struct Key {
    const SoNode* root = nullptr;
    SbUniqueId rootId = 0;
    SbMatrix affine = SbMatrix::identity(), projection = SbMatrix::identity();
    SbViewportRegion viewport;
    bool operator==(const Key& other) const;
  };

  static void initClass();
  // The decision kept in `state` for `key`; `decide` makes it when the kept one was
  // made for another key (or none was made yet).
  static const figment::StencilDecision& decisionFor(SoState* state, const Key& key,
                                                     const std::function<figment::StencilDecision()>& decide);

  void init(SoState* state) override;
  SbBool matches(const SoElement* element) const override;
  SoElement* copyMatchInfo() const override;

 protected:
  ~StencilDecisionElement() override;

 private:
  // Mutable: the cache fills while Coin hands out the element as const (it is read
  // through getConstElement, which never pushes a copy).
  mutable bool decided_ = false;
  mutable Key key_;
  mutable figment::StencilDecision decision_;
};

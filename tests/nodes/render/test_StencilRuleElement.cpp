// Whether the stencil rule decides: on by default in a render's state, set per state and
// undone with it, as a separator pops it.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>
#include <gtest/gtest.h>

#include "nodes/render/StencilRuleElement.h"
#include "support/SceneTestSupport.h"

namespace {

TEST(StencilRuleElement, OnByDefaultAndSetPerState) {
  figment::test::initCoin();
  SoGLRenderAction action(SbViewportRegion(10, 10));
  SoState* state = action.getState();
  EXPECT_TRUE(StencilRuleElement::get(state));
  state->push();
  StencilRuleElement::set(state, false);
  EXPECT_FALSE(StencilRuleElement::get(state));
  state->pop();  // as a separator undoes it
  EXPECT_TRUE(StencilRuleElement::get(state));
}

}  // namespace

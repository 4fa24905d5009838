// StencilDecisionElement: the stencil rule's decision is kept per render action, for
// the scene and view it was made for; another action's render never replaces it.
#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>
#include <Inventor/nodes/SoSeparator.h>
#include <gtest/gtest.h>

#include "nodes/render/StencilDecisionElement.h"
#include "support/SceneTestSupport.h"

using namespace figment::test;

namespace {

class StencilDecisionElementTest : public ::testing::Test {
 protected:
  void SetUp() override { initCoin(); }

  // Asks `action`'s state for the decision for `root`, counting the decisions made.
  const figment::StencilDecision& decide(SoGLRenderAction& action, SoNode* root) {
    StencilDecisionElement::Key key;
    key.root = root;
    key.rootId = root->getNodeId();
    key.viewport = action.getViewportRegion();
    return StencilDecisionElement::decisionFor(action.getState(), key, [&] {
      ++decisions_;
      figment::StencilDecision decision;
      decision.masked.push_back(root);  // marks whose decision this is
      return decision;
    });
  }

  int decisions_ = 0;
};

}  // namespace

TEST_F(StencilDecisionElementTest, ASecondAskForTheSameSceneAndViewDecidesNothing) {
  SoGLRenderAction action(SbViewportRegion(100, 80));
  auto* scene = new SoSeparator;
  scene->ref();
  decide(action, scene);
  EXPECT_TRUE(decide(action, scene).masks(scene));
  EXPECT_EQ(decisions_, 1);
  scene->addChild(new SoSeparator);  // the scene changed: its node id did
  decide(action, scene);
  EXPECT_EQ(decisions_, 2);
  scene->unref();
}

TEST_F(StencilDecisionElementTest, EachActionKeepsItsOwnDecision) {
  SoGLRenderAction first(SbViewportRegion(100, 80)), second(SbViewportRegion(100, 80));
  auto* a = new SoSeparator;
  a->ref();
  auto* b = new SoSeparator;
  b->ref();
  decide(first, a);
  EXPECT_TRUE(decide(second, b).masks(b));
  EXPECT_EQ(decisions_, 2);
  // The first action's decision for `a` outlived the second's for `b`: one cache for
  // the process would have had to decide `a` again.
  EXPECT_TRUE(decide(first, a).masks(a));
  EXPECT_FALSE(decide(first, a).masks(b));
  EXPECT_EQ(decisions_, 2);
  a->unref();
  b->unref();
}

TEST_F(StencilDecisionElementTest, AnotherViewportDecidesAgain) {
  SoGLRenderAction action(SbViewportRegion(100, 80));
  auto* scene = new SoSeparator;
  scene->ref();
  decide(action, scene);
  action.setViewportRegion(SbViewportRegion(200, 80));
  decide(action, scene);
  EXPECT_EQ(decisions_, 2);
  scene->unref();
}

// The nodes a node links to (children, then nodes held in SFNode/MFNode fields), and the walk
// over a scene that visits each linked node once, in scene order, and stops at a problem.
#include <Inventor/SoDB.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoVertexProperty.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "guard/NodeLinks.h"

using namespace figment::guard;

namespace {

class NodeLinksTest : public testing::Test {
 protected:
  // root { inner { cube }, cube, faces (vertexProperty: properties) }
  void SetUp() override {
    SoDB::init();
    root_ = new SoSeparator;
    root_->ref();
    inner_ = new SoSeparator;
    cube_ = new SoCube;
    faces_ = new SoIndexedFaceSet;
    properties_ = new SoVertexProperty;
    faces_->vertexProperty = properties_;
    inner_->addChild(cube_);
    root_->addChild(inner_);
    root_->addChild(cube_);
    root_->addChild(faces_);
  }
  void TearDown() override { root_->unref(); }
  SoSeparator *root_ = nullptr, *inner_ = nullptr;
  SoCube* cube_ = nullptr;
  SoIndexedFaceSet* faces_ = nullptr;
  SoVertexProperty* properties_ = nullptr;
};

TEST_F(NodeLinksTest, ChildrenEachAsOftenAsHeldThenFieldNodes) {
  inner_->addChild(cube_);  // held twice
  EXPECT_EQ(linkedNodes(*inner_), (std::vector<SoNode*>{cube_, cube_}));
  EXPECT_EQ(linkedNodes(*faces_), (std::vector<SoNode*>{properties_}));
  EXPECT_TRUE(linkedNodes(*cube_).empty());
  ASSERT_EQ(nodeFields(*faces_).size(), 1u);
  EXPECT_EQ(nodeFields(*faces_)[0], &faces_->vertexProperty);
}

TEST_F(NodeLinksTest, DescribesANodeByTypeAndName) {
  EXPECT_EQ(describeNode(*cube_), "Cube");
  cube_->setName("Box");
  EXPECT_EQ(describeNode(*cube_), "Cube 'Box'");
}

TEST_F(NodeLinksTest, VisitsEachLinkedNodeOnceInSceneOrder) {
  std::vector<const SoNode*> visited;
  EXPECT_EQ(firstProblemAmongLinkedNodes(root_,
                                         [&](const SoNode& node) {
                                           visited.push_back(&node);
                                           return std::string();
                                         }),
            "");
  EXPECT_EQ(visited, (std::vector<const SoNode*>{root_, inner_, cube_, faces_, properties_}));
}

TEST_F(NodeLinksTest, StopsAtTheFirstProblem) {
  int visits = 0;
  const std::string problem = firstProblemAmongLinkedNodes(root_, [&](const SoNode& node) {
    ++visits;
    return node.isOfType(SoCube::getClassTypeId()) ? describeNode(node) + ": bad" : std::string();
  });
  EXPECT_EQ(problem, "Cube: bad");
  EXPECT_EQ(visits, 3);  // root, inner, cube: nothing after it
}

}  // namespace

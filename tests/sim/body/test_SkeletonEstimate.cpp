// The skeleton estimate refuses what is not a standing humanoid, saying so: a mesh with no
// feet below and head above (a box), and one without vertices.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/body/SkeletonEstimate.h"
#include "support/BoxFigure.h"

using namespace figment;

namespace {

TEST(SkeletonEstimate, ABoxIsNoStandingHumanoid) {
  try {
    estimateSkeleton(mannequin::boxMesh({{0, 0, 0}, {0.3, 1.8, 0.3}}));
    FAIL() << "a box got a skeleton";
  } catch (const std::invalid_argument& e) {
    EXPECT_FALSE(std::string(e.what()).empty());
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();  // one line
  }
  EXPECT_THROW(estimateSkeleton(TriangleMesh{}), std::invalid_argument);
}

}  // namespace

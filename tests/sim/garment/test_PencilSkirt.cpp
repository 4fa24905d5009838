// The pencil skirt's options: each out of range refused naming the field, before any body is
// looked at; a body without triangles refused.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/garment/PencilSkirt.h"
#include "support/Refusal.h"

namespace test_PencilSkirt {

using namespace figment;

namespace {

std::string refusal(const PencilSkirtOptions& options) {
  return test::refusal([&] { options.validate(); });
}

TEST(PencilSkirt, RefusesEachBadOptionNamingIt) {
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({.waistEase = -0.01}), "waistEase = -0.01 must be >= 0");
  EXPECT_EQ(refusal({.hipEase = -0.01}), "hipEase = -0.01 must be >= 0");
  EXPECT_EQ(refusal({.length = -1}), "length = -1 must be > 0");
  EXPECT_EQ(refusal({.rows = 1}), "rows = 1 must be >= 2");
  EXPECT_EQ(refusal({.columns = 4}), "columns = 4 must be >= 8");
  EXPECT_EQ(refusal({.torsoHalfWidth = 0}), "torsoHalfWidth = 0 must be > 0");
}

TEST(PencilSkirt, ABadOptionIsRefusedBeforeTheBody) {
  try {
    makePencilSkirt(TriangleMesh{}, {.columns = 4});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "columns = 4 must be >= 8");
  }
  EXPECT_THROW(makePencilSkirt(TriangleMesh{}), std::invalid_argument);
}

}  // namespace

}  // namespace test_PencilSkirt

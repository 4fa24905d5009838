// The T-shirt's options: each out of range refused naming the field, before the body is
// looked at; a body without triangles refused.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sim/garment/TShirt.h"
#include "support/Refusal.h"

using namespace figment;

namespace {

std::string refusal(const TShirtOptions& options) {
  return test::refusal([&] { options.validate(); });
}

TEST(TShirt, RefusesEachBadOptionNamingIt) {
  EXPECT_EQ(refusal({}), "");
  EXPECT_EQ(refusal({.ease = -0.01}), "ease = -0.01 must be >= 0");
  EXPECT_EQ(refusal({.hemAboveCrotch = -0.1}), "hemAboveCrotch = -0.1 must be >= 0");
  EXPECT_EQ(refusal({.sleeveShare = 1.0}), "sleeveShare = 1 must be in (0, 1)");
  EXPECT_EQ(refusal({.sleeveShare = 0.0}), "sleeveShare = 0 must be in (0, 1)");
  EXPECT_EQ(refusal({.necklineDrop = -0.03}), "necklineDrop = -0.03 must be >= 0");
  EXPECT_EQ(refusal({.triangles = 0}), "triangles = 0 must be > 0");
}

TEST(TShirt, ABadOptionIsRefusedBeforeTheBody) {
  try {
    makeTShirt(TriangleMesh{}, {.triangles = -5});
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "triangles = -5 must be > 0");
  }
  EXPECT_THROW(makeTShirt(TriangleMesh{}), std::invalid_argument);
}

}  // namespace

// The up axes: each rotation takes its axis onto +y and is proper (a right-handed frame
// stays right-handed, so windings survive); names read back; fileUpAxis inverts toYUp.
#include <gtest/gtest.h>

#include <optional>
#include <utility>

#include "io/UpAxis.h"

using namespace figment;

namespace {

// Each axis and its direction in the file's coordinates, written out.
const std::pair<UpAxis, Vec3> kAxes[] = {{UpAxis::X, Vec3::UnitX()},     {UpAxis::Y, Vec3::UnitY()},
                                         {UpAxis::Z, Vec3::UnitZ()},     {UpAxis::NegX, -Vec3::UnitX()},
                                         {UpAxis::NegY, -Vec3::UnitY()}, {UpAxis::NegZ, -Vec3::UnitZ()}};

TEST(UpAxis, EachRotationTakesItsAxisUpAndKeepsHandedness) {
  for (const auto& [up, direction] : kAxes) {
    EXPECT_EQ(toYUp(direction, up), Vec3::UnitY()) << upAxisName(up);
    Eigen::Matrix3d m;
    for (int c = 0; c < 3; ++c) m.col(c) = toYUp(Vec3::Unit(c), up);
    EXPECT_DOUBLE_EQ(m.determinant(), 1.0) << upAxisName(up);
    EXPECT_TRUE((m.transpose() * m).isIdentity()) << upAxisName(up);
  }
}

TEST(UpAxis, NamesReadBackInAnyCaseAndNothingElseReads) {
  for (const auto& [up, direction] : kAxes) EXPECT_EQ(parseUpAxis(upAxisName(up)), up) << upAxisName(up);
  EXPECT_EQ(upAxisName(UpAxis::NegZ), "NEG_Z");
  EXPECT_EQ(parseUpAxis("neg_x"), UpAxis::NegX);
  EXPECT_EQ(parseUpAxis("-X"), std::nullopt);
  EXPECT_EQ(parseUpAxis(""), std::nullopt);
}

TEST(UpAxis, FileUpAxisFindsTheFileAxisThatEndedUp) {
  // Imported as Z up: what stands along +y was the file's +z; what stands along +z was -y.
  EXPECT_EQ(fileUpAxis(Vec3::UnitY(), UpAxis::Z), UpAxis::Z);
  EXPECT_EQ(fileUpAxis(Vec3::UnitZ(), UpAxis::Z), UpAxis::NegY);
  for (const auto& [applied, unused] : kAxes)
    for (const auto& [up, direction] : kAxes) EXPECT_EQ(fileUpAxis(toYUp(direction, applied), applied), up);
  EXPECT_EQ(fileUpAxis(Vec3(1, 1, 0).normalized(), UpAxis::Y), std::nullopt);
}

}  // namespace

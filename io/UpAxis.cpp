#include "io/UpAxis.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <utility>

namespace figment {

namespace {

// Each axis with its name and its direction in the file's coordinates.
const std::array<std::pair<UpAxis, const char*>, 6> kNames = {{{UpAxis::X, "X"},
                                                               {UpAxis::Y, "Y"},
                                                               {UpAxis::Z, "Z"},
                                                               {UpAxis::NegX, "NEG_X"},
                                                               {UpAxis::NegY, "NEG_Y"},
                                                               {UpAxis::NegZ, "NEG_Z"}}};

Vec3 direction(UpAxis up) {
  switch (up) {
    case UpAxis::X:
      return Vec3::UnitX();
    case UpAxis::Y:
      return Vec3::UnitY();
    case UpAxis::Z:
      return Vec3::UnitZ();
    case UpAxis::NegX:
      return -Vec3::UnitX();
    case UpAxis::NegY:
      return -Vec3::UnitY();
    case UpAxis::NegZ:
      return -Vec3::UnitZ();
  }
  return Vec3::UnitY();
}

}  // namespace

Vec3 toYUp(const Vec3& p, UpAxis up) {
  switch (up) {
    case UpAxis::Y:
      return p;
    case UpAxis::Z:
      return {p.x(), p.z(), -p.y()};  // -90 degrees about x
    case UpAxis::X:
      return {-p.y(), p.x(), p.z()};  // +90 degrees about z
    case UpAxis::NegY:
      return {p.x(), -p.y(), -p.z()};  // 180 degrees about x
    case UpAxis::NegZ:
      return {p.x(), -p.z(), p.y()};  // +90 degrees about x
    case UpAxis::NegX:
      return {p.y(), -p.x(), p.z()};  // -90 degrees about z
  }
  return p;
}

std::string upAxisName(UpAxis up) {
  for (const auto& [axis, name] : kNames)
    if (axis == up) return name;
  return "Y";
}

std::optional<UpAxis> parseUpAxis(const std::string& name) {
  std::string upper = name;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  for (const auto& [axis, axisName] : kNames)
    if (upper == axisName) return axis;
  return std::nullopt;
}

std::optional<UpAxis> fileUpAxis(const Vec3& up, UpAxis applied) {
  for (const auto& [axis, name] : kNames)
    if ((toYUp(direction(axis), applied) - up).norm() < 1e-9) return axis;
  return std::nullopt;
}

}  // namespace figment

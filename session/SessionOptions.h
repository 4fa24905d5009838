#pragma once
// What a front end asks of a scene session's images: their size in pixels and the
// direction the camera looks from. Plain values: figment-view reads them from its
// command line (viewer/ViewOptions.h), another front end from wherever it likes.

namespace figment::session {

struct ImageSize {
  int width = 800;
  int height = 600;
};

// Where the camera looks from, in degrees: azimuth about +y from +z (front, 0) towards
// +x (right, 90), elevation above the horizontal plane, in (-90, 90).
struct ViewDirection {
  double azimuth = 0.0;
  double elevation = 0.0;
};

}  // namespace figment::session

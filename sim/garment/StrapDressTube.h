#pragma once
// The strap dress's tube (StrapDress.h): rows of vertices around one vertical axis, from the
// top edge to the hem, each clear of the body's torso section by the clearance, and the top
// edge raised between the straps (the neckline). Method at the top of StrapDressTube.cpp.

#include <cmath>
#include <vector>

#include "sim/body/BodySlices.h"

namespace figment {

// Where the top edge rises: by `rise` (m) where the unraised top edge has
// |x - centreX| <= plateau (between the straps' centre lines), front and back, fading to no
// rise at plateau + fade by a smoothstep in |x|. Down the tube the rows above `fullRows` are
// raised as much as the top edge (the bust lies between them), then the rise shrinks linearly
// to none at row `rows`.
struct Neckline {
  double rise = 0;     // m
  double centreX = 0;  // m, the torso's centre
  double plateau = 0;  // m
  double fade = 0.04;  // m
  int fullRows = 2;    // rows raised by the whole rise, from the top edge down
  int rows = 6;        // rows raised at all (at most the tube's; more than fullRows)
};

class StrapDressTube {
 public:
  // Rows from `top` down to `hem` (their heights before the neckline's rise); a row's band of
  // sections reaches half a row up and down, but not above `ceiling` (where the arms join the
  // torso: their sections would count) unless the vertex itself is above it.
  // Throws std::invalid_argument where a section does not surround the tube's axis.
  StrapDressTube(const TriangleMesh& body, double top, double hem, double ceiling, int rows, double clearance,
                 double hemFlare, const SliceOptions& slicing, const Neckline& neckline);

  int rowCount() const { return static_cast<int>(heights_.size()); }
  double height(int row) const { return heights_[row]; }  // m, before the neckline's rise

  // The unraised rows, around which the columns are laid out. Angles in radians, theta = 0
  // along +x, pi/2 along +z. Distance from the axis of row `row` at `angle`: clear of every
  // section of its band and, below the hips, of the rows above it, plus the flare.
  double radius(int row, double angle) const;
  Vec2 point(double angle, double r) const { return axis_ + r * direction(angle); }
  Vec2 point(int row, double angle) const { return point(angle, radius(row, angle)); }
  // Arc length along an unraised row, counter-clockwise from the front centre to `angle`, and
  // back; both interpolate the same table, so they are each other's inverse.
  double perimeter(int row) const { return arcs_[row].back(); }
  double arcTo(int row, double angle) const;
  double angleAtArc(int row, double length) const;

  // The neckline's rise (m) of row `row` at `angle`; exactly 0 outside it.
  double rise(int row, double angle) const;
  // The mesh vertex of row `row` at `angle`: raised by rise(), its radius then taken from the
  // body's sections around its own height (half the way to the rows above and below).
  Vec3 vertex(int row, double angle) const;

  static Vec2 direction(double angle) { return {std::cos(angle), std::sin(angle)}; }

 private:
  void sliceRows(const TriangleMesh& body, double top, double hem, int rows, const SliceOptions& slicing);
  void sliceNeckline(const TriangleMesh& body, const SliceOptions& slicing);
  const TorsoSlice& checkedSlice(const TorsoSlice& slice) const;
  double bodyRadius(int row, double angle) const;
  void shapeSkirt(double hemFlare);
  double sampledRadius(int row, int k) const;

  double clearance_;
  double ceiling_;
  double spacing_ = 0;  // m between unraised rows
  Neckline neckline_;
  std::vector<double> heights_;
  std::vector<std::vector<TorsoSlice>> sections_;  // per row, its band's sections
  Vec2 axis_ = Vec2::Zero();
  int hips_ = 0;
  std::vector<double> flare_;                     // m, per row
  std::vector<std::vector<double>> bodySamples_;  // bodyRadius per row at the sampled angles
  std::vector<std::vector<double>> arcs_;         // per row, arc length at the sampled angles, closed
  double necklineBottom_ = 0;                     // m, the first of necklineSlices_
  std::vector<TorsoSlice> necklineSlices_;        // every kNecklineSliceStep up from necklineBottom_
};

}  // namespace figment

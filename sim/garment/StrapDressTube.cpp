// The strap dress's tube. Method:
// 1. Rows at fixed heights around one vertical axis (the mean centroid of the rows' torso
//    sections). Along the ray at angle theta from the axis, a row's radius is where the ray
//    leaves the torso's convex section offset by the clearance, the widest of several sections
//    within half a row above and below (nothing between two rows pokes through). Convex
//    sections span the gap between the legs and the cleavage as a tube of cloth does.
// 2. Below the hips (the widest row under the waist) no row is narrower than those above it,
//    plus a flare growing linearly to the hem: an A-line skirt that falls free of the thighs.
// 3. The neckline: in A-pose the arms join the torso at the armpits, so the top edge stays
//    under them at the sides, but between the straps, front and back, it rises to cover the
//    bust. The rise is a function of the unraised top edge's x (a smoothstep fade, C1, beyond
//    the straps' centre lines); the row below the top edge is raised as much, so that the bust
//    lies between the two even after the drape lowers the dress a few centimetres, then the
//    rise fades out linearly over the next rows. A raised vertex
//    keeps its row's angle; its radius comes from the sections around its own height, sampled
//    on a 1 mm stack (floored, so a band capped at the armpits stays under them).

#include "sim/garment/StrapDressTube.h"

#include <algorithm>
#include <stdexcept>

#include "sim/core/ParameterChecks.h"

namespace figment {

namespace {

constexpr double kTwoPi = 2.0 * M_PI;
constexpr double kFrontCentre = 0.5 * M_PI;   // the angle pointing +z, where arc lengths start
constexpr int kSectionsPerRow = 5;            // sections sampled within each row's band
constexpr int kAngleSamples = 720;            // around each row, for arc lengths
constexpr double kNecklineSliceStep = 0.001;  // m between the sections stacked for raised vertices

double sampleAngle(int k) {
  return kFrontCentre + kTwoPi * k / kAngleSamples;
}

double smoothstep(double t) {
  return t * t * (3 - 2 * t);
}

}  // namespace

StrapDressTube::StrapDressTube(const TriangleMesh& body, double top, double hem, double ceiling, int rows,
                               double clearance, double hemFlare, const SliceOptions& slicing, const Neckline& neckline)
    : clearance_(clearance), ceiling_(ceiling), neckline_(neckline) {
  neckline_.rows = std::clamp(neckline_.rows, 1, rows);
  neckline_.fullRows = std::clamp(neckline_.fullRows, 0, neckline_.rows - 1);
  sliceRows(body, top, hem, rows, slicing);
  shapeSkirt(hemFlare);
  for (int i = 0; i <= rows; ++i) {
    std::vector<double> arc = {0.0};
    for (int k = 1; k <= kAngleSamples; ++k) {
      const Vec2 previous = point(sampleAngle(k - 1), sampledRadius(i, k - 1));
      const Vec2 next = point(sampleAngle(k), sampledRadius(i, k % kAngleSamples));
      arc.push_back(arc.back() + (next - previous).norm());
    }
    arcs_.push_back(std::move(arc));
  }
  if (neckline_.rise > 0) sliceNeckline(body, slicing);
}

double StrapDressTube::radius(int row, double angle) const {
  double r = bodyRadius(row, angle);
  for (int above = hips_; above < row; ++above) r = std::max(r, bodyRadius(above, angle));
  return r + flare_[row];
}

double StrapDressTube::arcTo(int row, double angle) const {
  const double turns = (angle - kFrontCentre) / kTwoPi;
  const double k = (turns - std::floor(turns)) * kAngleSamples;
  const int i = std::min(static_cast<int>(k), kAngleSamples - 1);
  return arcs_[row][i] + (k - i) * (arcs_[row][i + 1] - arcs_[row][i]);
}

double StrapDressTube::angleAtArc(int row, double length) const {
  const std::vector<double>& arc = arcs_[row];
  length -= perimeter(row) * std::floor(length / perimeter(row));
  const int i = std::clamp(static_cast<int>(std::upper_bound(arc.begin(), arc.end(), length) - arc.begin()) - 1, 0,
                           kAngleSamples - 1);
  return sampleAngle(i) + (sampleAngle(i + 1) - sampleAngle(i)) * (length - arc[i]) / (arc[i + 1] - arc[i]);
}

double StrapDressTube::rise(int row, double angle) const {
  if (neckline_.rise == 0 || row >= neckline_.rows) return 0;
  const double beyond = std::abs(point(0, angle).x() - neckline_.centreX) - neckline_.plateau;
  const double t = std::clamp(beyond / neckline_.fade, 0.0, 1.0);
  if (t == 1) return 0;
  const double down = std::min(1.0, static_cast<double>(neckline_.rows - row) / (neckline_.rows - neckline_.fullRows));
  return neckline_.rise * (1 - smoothstep(t)) * down;
}

Vec3 StrapDressTube::vertex(int row, double angle) const {
  const double lift = rise(row, angle);
  if (lift == 0) {
    const Vec2 p = point(row, angle);
    return {p.x(), heights_[row], p.y()};
  }
  const double y = heights_[row] + lift;
  const double below = row + 1 < rowCount() ? y - heights_[row + 1] - rise(row + 1, angle) : spacing_;
  const double above = row > 0 ? heights_[row - 1] + rise(row - 1, angle) - y : spacing_;
  const double low = y - 0.5 * below, high = std::max(y, std::min(ceiling_, y + 0.5 * above));
  double r = 0;
  for (int s = 0; s < kSectionsPerRow; ++s) {
    const double h = low + (high - low) * s / (kSectionsPerRow - 1);
    const int k = std::clamp(static_cast<int>(std::floor((h - necklineBottom_) / kNecklineSliceStep)), 0,
                             static_cast<int>(necklineSlices_.size()) - 1);
    if (!necklineSlices_[k].empty()) r = std::max(r, necklineSlices_[k].reach(axis_, direction(angle), clearance_));
  }
  for (int over = hips_; over < row; ++over) r = std::max(r, bodyRadius(over, angle));
  const Vec2 p = point(angle, r + flare_[row]);
  return {p.x(), y, p.y()};
}

void StrapDressTube::sliceRows(const TriangleMesh& body, double top, double hem, int rows,
                               const SliceOptions& slicing) {
  spacing_ = (top - hem) / rows;
  Vec2 centroidSum = Vec2::Zero();
  for (int i = 0; i <= rows; ++i) {
    const double y = top - i * spacing_;
    heights_.push_back(y);
    const TorsoSlice own = sliceTorso(body, y, slicing);
    if (own.empty()) throw std::invalid_argument("body: no torso section at y = " + formatNumber(y));
    centroidSum += own.centroid();
    const double low = y - 0.5 * spacing_, high = std::max(y, std::min(ceiling_, y + 0.5 * spacing_));
    std::vector<TorsoSlice> band;
    for (int s = 0; s < kSectionsPerRow; ++s) {
      TorsoSlice slice = sliceTorso(body, low + (high - low) * s / (kSectionsPerRow - 1), slicing);
      if (!slice.empty()) band.push_back(std::move(slice));
    }
    sections_.push_back(std::move(band));
  }
  axis_ = centroidSum / (rows + 1);
  for (const auto& band : sections_)
    for (const TorsoSlice& slice : band) checkedSlice(slice);
}

// Every section a raised vertex may sample: from the lowest row the rise reaches up to half a
// row above the raised top edge.
void StrapDressTube::sliceNeckline(const TriangleMesh& body, const SliceOptions& slicing) {
  necklineBottom_ = heights_[neckline_.rows] - kNecklineSliceStep;
  const double topmost = heights_[0] + neckline_.rise + spacing_;
  const int count = static_cast<int>(std::ceil((topmost - necklineBottom_) / kNecklineSliceStep)) + 1;
  for (int k = 0; k < count; ++k)
    necklineSlices_.push_back(checkedSlice(sliceTorso(body, necklineBottom_ + k * kNecklineSliceStep, slicing)));
}

const TorsoSlice& StrapDressTube::checkedSlice(const TorsoSlice& slice) const {
  if (!slice.empty() && !slice.contains(axis_))
    throw std::invalid_argument("body: the section at y = " + formatNumber(slice.height) +
                                " does not surround the dress's axis (x = " + formatNumber(axis_.x()) +
                                ", z = " + formatNumber(axis_.y()) + ")");
  return slice;
}

double StrapDressTube::bodyRadius(int row, double angle) const {
  double r = 0;
  for (const TorsoSlice& slice : sections_[row]) r = std::max(r, slice.reach(axis_, direction(angle), clearance_));
  return r;
}

// Finds the hips (the widest row below the waist, the first row from the top narrower than
// the next: the knees may be narrower still) and the flare, growing linearly from 0 there to
// hemFlare at the hem. Samples bodyRadius around every row for this and for the arc tables.
void StrapDressTube::shapeSkirt(double hemFlare) {
  const int rows = rowCount();
  std::vector<double> mean(rows, 0.0);
  bodySamples_.assign(rows, std::vector<double>(kAngleSamples));
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < kAngleSamples; ++k) {
      bodySamples_[i][k] = bodyRadius(i, sampleAngle(k));
      mean[i] += bodySamples_[i][k] / kAngleSamples;
    }
  int waist = 0;
  while (waist + 1 < rows && mean[waist + 1] < mean[waist]) ++waist;
  hips_ = static_cast<int>(std::max_element(mean.begin() + waist, mean.end()) - mean.begin());
  flare_.assign(rows, 0.0);
  for (int i = hips_ + 1; i < rows; ++i)
    flare_[i] = hemFlare * (heights_[hips_] - heights_[i]) / (heights_[hips_] - heights_[rows - 1]);
}

double StrapDressTube::sampledRadius(int row, int k) const {
  double r = bodySamples_[row][k];
  for (int above = hips_; above < row; ++above) r = std::max(r, bodySamples_[above][k]);
  return r + flare_[row];
}

}  // namespace figment

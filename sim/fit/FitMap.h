#pragma once
// The fit map: a draped garment coloured by its stretch, ease or pressure at each node, in
// CLO's convention: blue at rest (no stretch, no pressure; for ease, far from the skin) to
// red at the fabric's limit (for ease, on the skin), in eight bands of one colour each, so
// a band reads as a range of values. What figment-size --fit-map draws; the bands and
// their values: docs/sizes.md.

#include <string>
#include <vector>

#include "sim/fit/FitVerdict.h"
#include "sim/fit/GarmentFit.h"

namespace figment {

enum class FitMapKind { Stretch, Ease, Pressure };
// "stretch", "ease", "pressure" -> the kind; throws std::invalid_argument naming the text.
FitMapKind fitMapKind(const std::string& name);

inline constexpr int kFitMapBands = 8;
inline constexpr double kEaseMapRange = 0.05;  // m: the ease map's blue end (5 cm off the skin)

// Each node's value: its sections' largest principal strain (area-weighted mean of the
// sections it is a corner of), its distance from the skin less the clearance (m), or its
// pressure (Pa, contactPressures).
std::vector<double> fitMapValues(const FitInput& input, FitMapKind kind);

// Where `value` lies from blue (0) to red (1): strain or pressure over the fabric's limit,
// or 1 - ease / kEaseMapRange; clamped to [0, 1].
double fitMapShare(double value, FitMapKind kind, const FabricLimits& limits);

// The band of `share` (0 to kFitMapBands - 1) and its colour: hue from blue (240 degrees)
// in the first band to red (0) in the last, full saturation and value; RGB in [0, 1].
int fitMapBand(double share);
Vec3 fitMapColour(int band);

// Each node's band: fitMapValues through fitMapShare and fitMapBand, what every fit-map
// drawing (figment-view, figment-size, the service) colours by.
std::vector<int> fitMapBands(const FitInput& input, FitMapKind kind, const FabricLimits& limits);

}  // namespace figment

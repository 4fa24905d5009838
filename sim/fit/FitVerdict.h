#pragma once
// One verdict per region of a draped garment (tight, fits, loose) and the line a shopper
// reads. A region is judged against the fabric's limits (how far it may stretch and press
// before it is tight) and against the style's intended fit there: the same size draped on
// its own chart body (its fit model), whose girth ease the region should keep within half
// a size step. Thresholds and the rule: docs/sizes.md.

#include <string>
#include <vector>

#include "sim/fit/GarmentFit.h"

namespace figment {

enum class Verdict { Tight, Fits, Loose };
const char* verdictName(Verdict verdict);  // "tight", "fits", "loose"

// A fabric's limits: beyond either a region is tight whatever the style intends.
struct FabricLimits {
  double stretch = 0.05;   // mean largest principal strain (0.05 = 5 %)
  double pressure = 2000;  // Pa, mean over the region's area
};
// The limits of a material preset's fabric (sim/cloth/MaterialPresets.h); the woven ones'
// for a name it does not know.
FabricLimits fabricLimits(const std::string& fabric);

struct VerdictRule {
  FabricLimits limits;
  // m of girth either side of the intended ease still told as fitting: half a chart step
  // (EN 13402-3's 4 cm), so a size up or down lands outside it.
  double girthTolerance = 0.02;
  // m a region's garment may hang lower than intended before it is loose (a skirt a size
  // too large slides down to where it grips).
  double dropTolerance = 0.02;
  // Stretch judged against the intended fit instead of the fabric's limits: tight past the
  // intended's mean strain by half a size step (girthTolerance over the intended garment
  // girth; the fabric's stretch limit where the region has no girth). For a garment sewn
  // from a graded pattern: its own size on its own chart body is the fit its maker graded,
  // stretch included, and the pattern's panels were placed for another body
  // (GarmentCode's), so the chart body strains it where the two differ (docs/sizes.md).
  // Pressure is then not judged apart: it is the stretch's tension over the body's radius.
  bool stretchAgainstIntended = false;
};

// `fit` judged against `intended` (the same region of the same size on its chart body).
// Tight past the fabric's stretch or pressure limit (or, with stretchAgainstIntended, past
// the intended stretch by half a size step), then by drop and girth ease against intended.
// A region the garment does not cover, or the intended one does not, is Fits; one whose
// girth the body's pose hides (RegionFit::unmeasured) is Tight past the fabric's limits, else Fits.
Verdict judge(const RegionFit& fit, const RegionFit& intended, const VerdictRule& rule);

// "tight at the hips: 7 % stretch; loose at the waist: 3 cm too much ease", or "fits
// everywhere" when no region is tight or loose. A tight region names its pressure or its
// stretch when past the fabric's limit, else the ease it lacks.
std::string shopperText(const std::vector<RegionFit>& fits, const std::vector<RegionFit>& intended,
                        const std::vector<Verdict>& verdicts, const VerdictRule& rule);

}  // namespace figment

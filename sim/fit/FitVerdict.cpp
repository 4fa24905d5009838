#include "sim/fit/FitVerdict.h"

#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iterator>

namespace figment {

namespace {

bool known(double value) {
  return std::isfinite(value);
}

// The strain `fit` may have beyond `intended`'s with stretchAgainstIntended: half a size
// step of girth over the intended garment girth (a size down is a full step, 4 cm, shorter).
double strainTolerance(const RegionFit& intended, const VerdictRule& rule) {
  return known(intended.garmentGirth) && intended.garmentGirth > 0 ? rule.girthTolerance / intended.garmentGirth
                                                                   : rule.limits.stretch;
}

bool overstretched(const RegionFit& fit, const RegionFit& intended, const VerdictRule& rule) {
  if (rule.stretchAgainstIntended) return fit.meanStrain > intended.meanStrain + strainTolerance(intended, rule);
  return fit.meanStrain > rule.limits.stretch || fit.pressure > rule.limits.pressure;
}

// Why a region is tight or loose, in a few words ("7 % stretch", "3 cm too little ease").
std::string reason(const RegionFit& fit, const RegionFit& intended, Verdict verdict, const VerdictRule& rule) {
  char text[96];
  const double girthDifference =
      known(fit.girthEase) && known(intended.girthEase) ? fit.girthEase - intended.girthEase : 0.0;
  const double low = fit.drop - intended.drop;
  if (verdict == Verdict::Tight && rule.stretchAgainstIntended && overstretched(fit, intended, rule))
    std::snprintf(text, sizeof text, "%.0f %% stretch, %.0f %% as made", 100.0 * fit.meanStrain,
                  100.0 * intended.meanStrain);
  else if (verdict == Verdict::Tight && !rule.stretchAgainstIntended && fit.pressure > rule.limits.pressure)
    std::snprintf(text, sizeof text, "%.1f kPa", fit.pressure / 1000.0);
  else if (verdict == Verdict::Tight && !rule.stretchAgainstIntended && fit.meanStrain > rule.limits.stretch)
    std::snprintf(text, sizeof text, "%.0f %% stretch", 100.0 * fit.meanStrain);
  else if (std::abs(low) > rule.dropTolerance && known(intended.girthEase))
    std::snprintf(text, sizeof text, low > 0 ? "hangs %.0f cm low" : "%.0f cm too high", 100.0 * std::abs(low));
  else if (girthDifference != 0)
    std::snprintf(text, sizeof text, "%.0f cm too %s ease", 100.0 * std::abs(girthDifference),
                  girthDifference < 0 ? "little" : "much");
  else
    std::snprintf(text, sizeof text, "%.0f mm from the skin", 1000.0 * fit.ease);
  return text;
}

}  // namespace

const char* verdictName(Verdict verdict) {
  static constexpr const char* kNames[] = {"tight", "fits", "loose"};  // in Verdict's order
  static_assert(static_cast<int>(Verdict::Tight) == 0 && static_cast<int>(Verdict::Loose) == 2);
  const auto index = static_cast<std::size_t>(verdict);
  return index < std::size(kNames) ? kNames[index] : "fits";
}

FabricLimits fabricLimits(const std::string& fabric) {
  // Knits give by their loops and are worn stretched; wovens barely extend before they
  // pull (docs/sizes.md: why these figures).
  if (fabric == "jersey") return {0.10, 2000};
  if (fabric == "denim") return {0.03, 2000};
  return {0.04, 2000};  // cotton, silk and other wovens
}

Verdict judge(const RegionFit& fit, const RegionFit& intended, const VerdictRule& rule) {
  if (!fit.covered() || !intended.covered()) return Verdict::Fits;
  if (overstretched(fit, intended, rule)) return Verdict::Tight;
  // Its girth and drop not told in the body's pose: its stretch and pressure alone.
  if (!fit.unmeasured.empty()) return Verdict::Fits;
  if (known(intended.girthEase) && fit.drop > intended.drop + rule.dropTolerance) return Verdict::Loose;
  if (known(intended.girthEase) && fit.drop < intended.drop - rule.dropTolerance) return Verdict::Tight;
  if (known(fit.girthEase) && known(intended.girthEase)) {
    if (fit.girthEase < intended.girthEase - rule.girthTolerance) return Verdict::Tight;
    if (fit.girthEase > intended.girthEase + rule.girthTolerance) return Verdict::Loose;
    return Verdict::Fits;
  }
  // No girth (shoulders, upper arms): the distance from the skin, by the radial share of
  // the same tolerance.
  const double radial = rule.girthTolerance / (2.0 * M_PI);
  if (fit.ease > intended.ease + radial) return Verdict::Loose;
  return Verdict::Fits;
}

std::string shopperText(const std::vector<RegionFit>& fits, const std::vector<RegionFit>& intended,
                        const std::vector<Verdict>& verdicts, const VerdictRule& rule) {
  std::string text;
  for (const Verdict wanted : {Verdict::Tight, Verdict::Loose})
    for (size_t r = 0; r < fits.size(); ++r) {
      if (verdicts[r] != wanted) continue;
      text += (text.empty() ? "" : "; ") + std::string(verdictName(wanted)) + " at the " + fits[r].name + ": " +
              reason(fits[r], intended[r], wanted, rule);
    }
  return text.empty() ? "fits everywhere" : text;
}

}  // namespace figment

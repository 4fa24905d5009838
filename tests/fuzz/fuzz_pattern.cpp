// libFuzzer target: the sewing-pattern reader (io/PatternFile.cpp) on any text. It either
// refuses with its one documented error, on one line, or returns a pattern that keeps the
// reader's promises: every edge of finite length no shorter than kMinEdgeLength, its
// samples finite, and each stitch's two lengths within kMaxStitchLengthRatio.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/PatternFile.h"
#include "sim/pattern/EdgeCurves.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace figment;
  SewingPattern pattern;
  try {
    pattern = parsePattern(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const PatternError& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) std::abort();
    return 0;
  }
  for (const Panel& panel : pattern.panels)
    for (int k = 0; k < static_cast<int>(panel.edges.size()); ++k) {
      const double length = edgeLength(panel, k);
      if (!std::isfinite(length) || length < kMinEdgeLength) std::abort();
      for (const Vec2& p : sampleEdge(panel, k, 4))
        if (!p.allFinite()) std::abort();
    }
  for (const Stitch& s : pattern.stitches) {
    const double a = edgeLength(pattern.panels[s.first.panel], s.first.edge);
    const double b = edgeLength(pattern.panels[s.second.panel], s.second.edge);
    if (std::max(a, b) > kMaxStitchLengthRatio * std::min(a, b) * (1 + 1e-12)) std::abort();
  }
  return 0;
}

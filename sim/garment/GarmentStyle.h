#pragma once
// The catalogue's styles: each garment generator with the ease it is cut with (m of girth
// over the body at bust, waist and hip: how much bigger than its body the garment is) and
// its fabric. A graded garment is a style cut around a size's chart body
// (sim/garment/SizeChart.h): a size-M dress is one fixed garment whatever body wears it.
// The table, and why each ease: docs/sizes.md.

#include <string>
#include <vector>

#include "sim/core/TriangleMesh.h"

namespace figment {

enum class StyleKind { StrapDress, FlaredSkirt, TShirt, PencilSkirt };

// Girth ease, m; 0 where the style does not reach (e.g. a skirt's bust).
struct StyleEase {
  double bust = 0, waist = 0, hip = 0;
};

struct GarmentStyle {
  const char* name;    // "dress", "skirt", "tshirt", "pencil"
  StyleKind kind;      // its generator
  StyleEase ease;      // as cut
  const char* fabric;  // a material preset (sim/cloth/MaterialPresets.h)
  const char* about;   // one line for --help and the docs
  // The body regions (sim/fit/FitRegion.h) its fit is told for: where it is shaped to the
  // body. A flared skirt's hips and thighs hang free, a dress's thighs are A-line.
  std::vector<std::string> regions;
  // Whether its sizes may start from each other's drapes (sim/fit/SizeFitter.h). Not for
  // a garment held up by friction alone (the flared skirt): it ends where it starts, so a
  // warm start would decide its fit.
  bool warmStarts = true;
};

// Every style, in a fixed order.
const std::vector<GarmentStyle>& garmentStyles();
// The style called `name`, or null.
const GarmentStyle* findStyle(const std::string& name);
// "dress, skirt, tshirt, pencil": for messages.
std::string styleNames();

// The style's garment cut around `body` (the size's chart body) with the style's ease.
// Throws std::invalid_argument as its generator does.
TriangleMesh cutGarment(const GarmentStyle& style, const TriangleMesh& body);

}  // namespace figment

#pragma once
// Headless rendering: Coin draws into an OSMesa context instead of a window system's.

namespace figment {

// Registers OSMesa context callbacks with Coin, so SoOffscreenRenderer renders with no
// display (24-bit depth, 8-bit stencil: the hybrid clothing renderer needs the stencil).
// Must come before the first SoDB::init(); safe to call more than once. A program using
// it links figment_headless, which also compiles GlxForwarding.cpp into it (without
// that, Coin's vertex-array drawing is silently blank).
void useOsmesaForCoin();

}  // namespace figment

#pragma once
// Internal to figment_nodes: field values as the scene wrote them.
//
// Coin's ASCII reader parses numbers with an error in the last binary digits: "0.0005"
// reads into an SFDouble as 0.0005000000000000001, and an SFFloat holds the nearest
// float, 0.000500000024. Passed on as they are, a scene's defaults would differ from
// sim/'s by a rounding error and messages would say "thickness = -0.0010000000000000002".
// These give back the decimal number the scene most likely wrote: the value rounded to
// the precision its field type keeps (15 significant digits for double, 7 for float).
// ClothEngine snaps its double fields when read (which also keeps a written and re-read
// file identical: 0.0007 would otherwise drift in its last digit on each round trip).

class SoFieldContainer;

namespace figment {

double writtenValue(double fieldValue);
double writtenValue(float fieldValue);

// Replaces each SoSFDouble field of `container` that was read (not default, not
// connected) by its writtenValue().
void snapReadDoubles(SoFieldContainer& container);

}  // namespace figment

#pragma once
// figment-view --frames: shows a recorded state of a garment in place of its drape.

#include <Inventor/SbVec3f.h>

#include <vector>

#include "nodes/cloth/ClothEngine.h"

namespace figment::session {

// Puts `positions` (one per rest point) wherever `engine`'s positions output is drawn:
// each point field it feeds stops following the engine (its connection disabled, not
// removed) and holds them. Fields of collision bodies (a GarmentSurface an outer
// garment drapes on) keep the drape: the layers over it were draped on that, and
// changing it would make them simulate again.
void showPositions(ClothEngine& engine, const std::vector<SbVec3f>& positions);

}  // namespace figment::session

#pragma once
// How a scene's drapes ended, as figment-serve's answers say it (the X-Figment-Drape header,
// docs/service.md): sim's DrapeVerdict (sim/cloth/DrapeVerdict.h) of each garment's run, the
// worst of them winning. Only a picture of drapes at rest is kept for another request.

#include <string>
#include <vector>

#include "sim/drape/DrapeReport.h"

class ClothEngine;

namespace figment::serve {

// A scene's drapes, from its engines (in scene order).
std::vector<DrapeReport> drapeReports(const std::vector<ClothEngine*>& engines);

// "torn" when an edge of one drape ended past the tear stretch or an implicit step of it
// failed at its smallest step; else "restless" when one still moved at its maxTime or was
// held by a limiter in its last step; else "rest" (also for no garment at all).
std::string drapeState(const std::vector<DrapeReport>& reports);

}  // namespace figment::serve

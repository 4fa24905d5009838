#pragma once
// ShopperChoices: the choices a request shares whatever its body (lights, skin tones),
// and the Mannequin's own: the paper's scanned body (body=mannequin), scaled to the
// measurements within the ranges its fitted volumes hold, posed by its joints and dressed
// in the paper's patterns as cut (the shipped scenes' dress, skirt and T-shirt: one size
// each, so an outfit item names no size). A shopper's own body and the catalogue's sized
// garments are MadeBodyChoices.h's. Plain data shared by the server (parsing requests, GET
// /api/catalogue) and its workers (building scenes): every file a scene reads is named
// here, in code, never by a request.

#include <array>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

namespace figment::serve {

// A measurement's accepted range, metres.
struct MeasureRange {
  std::string name;      // the request parameter: stature, bust, waist, hips
  double minimum = 0;    // m
  double maximum = 0;    // m
  double reference = 0;  // m, the default body's own measurement (factor 1)
};

struct BodyMeasures {
  double stature = 0, bust = 0, waist = 0, hips = 0;  // m
};

// Mannequin size factors (nodes/body/Mannequin.h: height, chest, waist, hips).
struct BodyFactors {
  double height = 1, chest = 1, waist = 1, hips = 1;
};

// How a style drapes: its pattern (a file beside the scenes), its solver settings.
struct GarmentStyle {
  std::string name;              // dress, skirt, tshirt
  std::string pattern;           // the pattern's file name, looked up in the scenes folder
  bool penaltyContacts = false;  // PENALTY contacts even as the innermost layer
  double maxTime = 5;            // s simulated at most
  std::string defaultColour;     // hex rrggbb
};

struct NamedColour {
  std::string name;  // fair, light, ...
  std::string hex;   // rrggbb
};

// A pose: joints of the default skeleton turned by axis-angle rotations (radians).
struct Pose {
  std::string name;
  std::vector<std::string> joints;
  std::vector<std::array<double, 4>> rotations;  // axis x y z, angle
};

// A light preset: directional lights (direction, intensity, colour rgb in [0,1]).
struct LightPreset {
  struct Light {
    std::array<double, 3> direction;
    double intensity;
    std::array<double, 3> colour;
  };
  std::string name;
  std::vector<Light> lights;
};

class ShopperChoices {
 public:
  static const std::vector<MeasureRange>& measures();
  static const std::vector<GarmentStyle>& styles();
  static const std::vector<std::string>& colours();  // suggested garment colours, hex
  static const std::vector<NamedColour>& skinTones();
  static const std::vector<Pose>& poses();
  static const std::vector<LightPreset>& lights();

  // Null when unknown.
  static const GarmentStyle* style(const std::string& name);
  static const Pose* pose(const std::string& name);
  static const LightPreset* light(const std::string& name);
  static const MeasureRange& measure(const std::string& name);  // one of measures()

  // The Mannequin at `body`: scaled by factors, each measurement over its own.
  static BodyFactors bodyFactors(const BodyMeasures& body);

  // GET /api/catalogue's part for the Mannequin (its styles, measurements and poses), and
  // the lights and skin tones every body takes.
  static nlohmann::json mannequinJson();
  static nlohmann::json sharedJson();
};

}  // namespace figment::serve

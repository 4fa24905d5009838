#include "serve/request/ShopperChoices.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace figment::serve {

namespace {

// The default body (human.zae) as figment-measure measures it (ISO 8559-1 landmarks,
// convex girths): stature 1.6594 m, bust 0.8906, waist 0.6956, hips 0.9388. The ranges
// keep today's factors where the fitted volumes still hold (about -12 % to +20 %).
const std::vector<MeasureRange> kMeasures = {
    {"stature", 1.45, 1.90, 1.6594},
    {"bust", 0.78, 1.10, 0.8906},
    {"waist", 0.60, 0.90, 0.6956},
    {"hips", 0.82, 1.15, 0.9388},
};

// Solver settings as the shipped scenes drape them (scenes/dress.iv, tshirt.iv,
// outfit-skirt.iv: backward Euler at 1/20 s); the skirt slides down to the hips (10 s).
const std::vector<GarmentStyle> kStyles = {
    {"dress", "dress.obj", false, 5, "1f40b3"},
    {"skirt", "skirt.obj", true, 10, "8c1f33"},
    {"tshirt", "tshirt.obj", true, 5, "d9d9d1"},
};

const std::vector<std::string> kColours = {"1f40b3", "d9d9d1", "8c1f33", "2e7d32",
                                           "c9a227", "222222", "f5f0e6", "6a1b9a"};

// "medium" is the shipped scenes' skin (0.80 0.58 0.45).
const std::vector<NamedColour> kSkinTones = {{"fair", "f3d5c0"}, {"light", "e8b996"}, {"medium", "cc9473"},
                                             {"tan", "a86b45"},  {"brown", "7c4a2d"}, {"deep", "4a2c1d"}};

// Poses that move no part through the garments' rest shapes (scenes/posed.iv's elbows
// and head; a raised arm would pass through an armhole and tangle the cloth).
const std::vector<Pose> kPoses = {
    {"rest", {}, {}},
    {"relaxed", {"elbowL", "elbowR"}, {{1, 0, 0, -0.6}, {1, 0, 0, -0.6}}},
    {"turn-head", {"neckTop"}, {{0, 1, 0, 0.4}}},
};

const std::vector<LightPreset> kLights = {
    {"studio", {{{-0.4, -0.5, -1}, 0.75, {1, 1, 1}}, {{0.6, -0.3, 0.8}, 0.5, {1, 1, 1}}}},
    {"soft",
     {{{0, -0.3, -1}, 0.5, {1, 1, 1}},
      {{-0.8, -0.2, -0.3}, 0.3, {1, 1, 1}},
      {{0.8, -0.2, -0.3}, 0.3, {1, 1, 1}},
      {{0, -0.5, 1}, 0.3, {1, 1, 1}}}},
    {"warm", {{{-0.4, -0.5, -1}, 0.8, {1, 0.85, 0.65}}, {{0.6, -0.3, 0.8}, 0.4, {1, 0.9, 0.8}}}},
    {"dramatic", {{{1, -0.3, -0.4}, 1.0, {1, 1, 1}}, {{-0.2, -0.2, 1}, 0.3, {0.7, 0.8, 1}}}},
};

template <class T>
const T* byName(const std::vector<T>& list, const std::string& name) {
  for (const T& item : list)
    if (item.name == name) return &item;
  return nullptr;
}

}  // namespace

const std::vector<MeasureRange>& ShopperChoices::measures() {
  return kMeasures;
}
const std::vector<GarmentStyle>& ShopperChoices::styles() {
  return kStyles;
}
const std::vector<std::string>& ShopperChoices::colours() {
  return kColours;
}
const std::vector<NamedColour>& ShopperChoices::skinTones() {
  return kSkinTones;
}
const std::vector<Pose>& ShopperChoices::poses() {
  return kPoses;
}
const std::vector<LightPreset>& ShopperChoices::lights() {
  return kLights;
}

const GarmentStyle* ShopperChoices::style(const std::string& name) {
  return byName(kStyles, name);
}
const Pose* ShopperChoices::pose(const std::string& name) {
  return byName(kPoses, name);
}
const LightPreset* ShopperChoices::light(const std::string& name) {
  return byName(kLights, name);
}

const MeasureRange& ShopperChoices::measure(const std::string& name) {
  if (const MeasureRange* range = byName(kMeasures, name)) return *range;
  throw std::invalid_argument("no measurement named " + name);
}

BodyFactors ShopperChoices::bodyFactors(const BodyMeasures& body) {
  return {body.stature / measure("stature").reference, body.bust / measure("bust").reference,
          body.waist / measure("waist").reference, body.hips / measure("hips").reference};
}

nlohmann::json ShopperChoices::mannequinJson() {
  nlohmann::json styles = nlohmann::json::array(), measures = nlohmann::json::object();
  for (const GarmentStyle& style : kStyles)
    styles.push_back({{"name", style.name}, {"colours", kColours}, {"defaultColour", style.defaultColour}});
  for (const MeasureRange& range : kMeasures)
    measures[range.name] = {
        {"unit", "m"}, {"min", range.minimum}, {"max", range.maximum}, {"default", range.reference}};
  nlohmann::json poses = nlohmann::json::array();
  for (const Pose& pose : kPoses) poses.push_back(pose.name);
  return {{"styles", styles}, {"measurements", measures}, {"poses", poses}};
}

nlohmann::json ShopperChoices::sharedJson() {
  nlohmann::json skin = nlohmann::json::array(), lights = nlohmann::json::array();
  for (const NamedColour& tone : kSkinTones) skin.push_back({{"name", tone.name}, {"hex", tone.hex}});
  for (const LightPreset& light : kLights) lights.push_back(light.name);
  return {{"lights", lights}, {"skinTones", skin}};
}

}  // namespace figment::serve

#include "serve/request/RenderRequest.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "serve/request/BodyMeasuresText.h"
#include "serve/request/MeasuredPoses.h"
#include "serve/request/Utf8Text.h"
#include "sim/garment/GarmentStyle.h"

namespace figment::serve {

namespace {

const char* const kNames[] = {"stature", "bust",  "chest", "waist", "hips",   "skin", "pose",
                              "outfit",  "light", "view",  "size",  "format", "sex",  "fitmap"};

ParameterError bad(const std::string& parameter, const std::string& value, const std::string& error,
                   const std::string& accepted) {
  return RequestParameters::refusal(parameter, value, error, accepted);
}

std::string formatted(const char* pattern, double a, double b = 0) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

bool isHex6(const std::string& text) {
  return text.size() == 6 &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isxdigit((unsigned char)c); });
}

std::string lower(std::string text) {
  for (char& c : text) c = char(std::tolower((unsigned char)c));
  return text;
}

std::string namesOf(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

template <class T>
std::string namesOf(const std::vector<T>& items) {
  std::vector<std::string> names;
  for (const T& item : items) names.push_back(item.name);
  return namesOf(names);
}

// `ranges`: a measured body's (its sex's, BodyMeasuresText::ranges); empty: the Mannequin's (ShopperChoices).
std::optional<ParameterError> measurement(const std::string& name, const std::string& value,
                                          const std::vector<MeasureRange>& ranges, double& out) {
  const std::string key = name == "chest" ? "bust" : name;
  const auto own = std::find_if(ranges.begin(), ranges.end(), [&](const MeasureRange& r) { return r.name == key; });
  return BodyMeasuresText::read(name, value, own != ranges.end() ? *own : ShopperChoices::measure(key), out);
}

// A tone by its name as ShopperChoices writes it, or hex in any case, optionally after '#'.
std::optional<ParameterError> skinTone(const std::string& value, std::string& out) {
  for (const NamedColour& tone : ShopperChoices::skinTones())
    if (tone.name == value) return out = tone.hex, std::nullopt;
  const std::string text = lower(value.size() == 7 && value[0] == '#' ? value.substr(1) : value);
  if (isHex6(text)) return out = text, std::nullopt;
  return bad("skin", value, "not a skin tone", "rrggbb (hex) or " + namesOf(ShopperChoices::skinTones()));
}

// The sizes an outfit item may name and the measurements' ranges: the Mannequin's
// ShopperChoices, or with a sex the chart's.
struct SizeNames {
  const SizeChart* chart = nullptr;  // null: the Mannequin's ShopperChoices
  Sex sex = Sex::Female;
  std::vector<MeasureRange> ranges;  // with a chart: the sex's (what /api/fit accepts)
};

std::string acceptedItems(const SizeNames& names) {
  if (!names.chart)
    return "style:size[:rrggbb], styles " + namesOf(ShopperChoices::styles()) + "; sizes " +
           namesOf(ShopperChoices::sizes());
  std::vector<std::string> sizes;
  for (const ChartSize& size : names.chart->sizes(names.sex)) sizes.push_back(size.name);
  return "style:size[:rrggbb], styles " + styleNames() + "; " + sexName(names.sex) + " sizes " + namesOf(sizes);
}

// A graded style's colour when it has none: ShopperChoices' for its name, else grey.
std::string defaultColour(const std::string& style) {
  const GarmentStyle* known = ShopperChoices::style(style);
  return known ? known->defaultColour : "8c8c8c";
}

std::optional<ParameterError> outfitItem(const std::string& value, const std::string& item, const SizeNames& names,
                                         OutfitItem& out) {
  const std::string accepted = acceptedItems(names);
  const size_t a = item.find(':'), b = a == std::string::npos ? a : item.find(':', a + 1);
  if (a == std::string::npos)
    return bad("outfit", value, "a garment without a size: " + Utf8Text::shown(item, 32), accepted);
  out.style = item.substr(0, a);
  out.size = item.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
  if (names.chart ? !findStyle(out.style) : !ShopperChoices::style(out.style))
    return bad("outfit", value, "no style named " + Utf8Text::shown(out.style, 32), accepted);
  if (names.chart ? names.chart->find(names.sex, out.size) < 0 : !ShopperChoices::size(out.size))
    return bad("outfit", value, "no size named " + Utf8Text::shown(out.size, 32), accepted);
  if (names.chart) out.size = names.chart->sizes(names.sex)[size_t(names.chart->find(names.sex, out.size))].name;
  out.colour = b == std::string::npos ? defaultColour(out.style) : lower(item.substr(b + 1));
  if (!isHex6(out.colour)) return bad("outfit", value, "not a colour: " + Utf8Text::shown(out.colour, 32), accepted);
  return std::nullopt;
}

std::optional<ParameterError> outfit(const std::string& value, const SizeNames& names, std::vector<OutfitItem>& out) {
  out.clear();
  if (value.empty() || value == "none") return std::nullopt;  // the body alone
  std::set<std::string> styles;
  size_t start = 0;
  while (start <= value.size()) {
    const size_t comma = std::min(value.find(',', start), value.size());
    if (int(out.size()) == RequestLimits::kMaxGarments)
      return bad("outfit", value, "too many garments", "at most 3, innermost first");
    OutfitItem item;
    if (auto error = outfitItem(value, value.substr(start, comma - start), names, item)) return error;
    if (!styles.insert(item.style).second)
      return bad("outfit", value, "a style worn twice: " + item.style, "each style once");
    out.push_back(item);
    start = comma + 1;
  }
  return std::nullopt;
}

// A Mannequin's pose is one of ShopperChoices'; a measured body's one of MakeHuman's rig presets.
std::optional<ParameterError> pose(const std::string& value, const SizeNames& names, std::string& out) {
  if (names.chart ? MeasuredPoses::find(value) != nullptr : ShopperChoices::pose(value) != nullptr)
    return out = value, std::nullopt;
  if (names.chart && ShopperChoices::pose(value))
    return bad("pose", value, "a measured body (sex) has MakeHuman's rig, not the Mannequin's joints",
               MeasuredPoses::names());
  return bad("pose", value, "no such pose", names.chart ? MeasuredPoses::names() : namesOf(ShopperChoices::poses()));
}

// Stretch needs the drape alone; ease and pressure the skin as a mesh, which a measured
// body has and the Mannequin (its skin drawn over collision volumes) has not.
std::optional<ParameterError> fitMap(const std::string& value, const SizeNames& names, std::string& out) {
  const std::string accepted = "stretch, none; with sex also ease, pressure";
  if (value == "stretch" || value == "none") return out = value == "none" ? "" : value, std::nullopt;
  if (value != "ease" && value != "pressure") return bad("fitmap", value, "no such fit map", accepted);
  if (!names.chart) return bad("fitmap", value, "ease and pressure need a measured body (sex)", accepted);
  return out = value, std::nullopt;
}

std::optional<ParameterError> view(const std::string& value, double& azimuth, double& elevation) {
  const std::string accepted = "AZ,EL in degrees (AZ -360 to 360, EL -60 to 80), or front, back, left, right";
  const std::map<std::string, double> named = {{"front", 0}, {"right", 90}, {"back", 180}, {"left", 270}};
  if (auto it = named.find(value); it != named.end()) return azimuth = it->second, elevation = 0, std::nullopt;
  const size_t comma = value.find(',');
  double az = 0, el = 0;
  if (comma == std::string::npos || !RequestParameters::number(value.substr(0, comma), az) ||
      !RequestParameters::number(value.substr(comma + 1), el))
    return bad("view", value, "not a view", accepted);
  if (std::abs(az) > 360 || el < -60 || el > 80) return bad("view", value, "out of range", accepted);
  az = std::round(az * 10.0) / 10.0;
  azimuth = std::fmod(az + 360.0, 360.0);
  elevation = std::round(el * 10.0) / 10.0 + 0.0;  // + 0.0: no "-0.0"
  return std::nullopt;
}

std::optional<ParameterError> imageSize(const std::string& value, int& width, int& height) {
  const std::string accepted = "WxH, each side 64 to 1600 pixels, at most 1600x1200 pixels in all";
  const size_t x = value.find('x');
  int w = 0, h = 0;
  const char* begin = value.data();
  const char* end = begin + value.size();
  if (x == std::string::npos || x == 0 || x + 1 == value.size() || value.size() > 9)
    return bad("size", value, "not a size", accepted);
  auto [p1, e1] = std::from_chars(begin, begin + x, w);
  auto [p2, e2] = std::from_chars(begin + x + 1, end, h);
  if (e1 != std::errc() || p1 != begin + x || e2 != std::errc() || p2 != end)
    return bad("size", value, "not a size", accepted);
  if (w < RequestLimits::kMinSide || h < RequestLimits::kMinSide || w > RequestLimits::kMaxSide ||
      h > RequestLimits::kMaxSide || w * h > RequestLimits::kMaxPixels)
    return bad("size", value, "too small or too large", accepted);
  width = w, height = h;
  return std::nullopt;
}

// The parameters as a map, each named once, each known.
std::variant<std::map<std::string, std::string>, ParameterError> byName(const QueryParameters& parameters) {
  std::map<std::string, std::string> values;
  const std::vector<std::string> known(std::begin(kNames), std::end(kNames));
  if (int(parameters.size()) > RequestLimits::kMaxParameters) return bad("", "", "too many parameters", "at most 16");
  for (const auto& [name, value] : parameters) {
    if (auto error = RequestParameters::textError(name, value)) return *error;
    if (std::find(known.begin(), known.end(), name) == known.end())
      return bad(Utf8Text::shown(name, 64), value, "unknown parameter", namesOf(known));
    if (value.size() > RequestLimits::kMaxValueLength) return bad(name, value, "value too long", "at most 200 bytes");
    if (!values.emplace(name, value).second) return bad(name, value, "given twice", "each parameter once");
  }
  if (values.count("bust") && values.count("chest") && values["bust"] != values["chest"])
    return bad("chest", values["chest"], "bust and chest differ", "one of them, or both the same");
  return values;
}

std::optional<ParameterError> fill(RenderRequest& request, const std::map<std::string, std::string>& values,
                                   const SizeNames& names) {
  std::optional<ParameterError> error;
  for (const auto& [name, value] : values) {
    if (name == "stature")
      error = measurement(name, value, names.ranges, request.body.stature);
    else if (name == "bust" || name == "chest")
      error = measurement(name, value, names.ranges, request.body.bust);
    else if (name == "waist")
      error = measurement(name, value, names.ranges, request.body.waist);
    else if (name == "hips")
      error = measurement(name, value, names.ranges, request.body.hips);
    else if (name == "skin")
      error = skinTone(value, request.skin);
    else if (name == "pose")
      error = pose(value, names, request.pose);
    else if (name == "light")
      error = ShopperChoices::light(value)
                  ? (request.light = value, std::nullopt)
                  : std::optional(bad(name, value, "no such light", namesOf(ShopperChoices::lights())));
    else if (name == "outfit")
      error = outfit(value, names, request.outfit);
    else if (name == "view")
      error = view(value, request.azimuth, request.elevation);
    else if (name == "size")
      error = imageSize(value, request.width, request.height);
    else if (name == "fitmap")
      error = fitMap(value, names, request.fitMap);
    else if (name == "format")
      error = value == "png" || value == "glb" ? (request.format = value, std::nullopt)
                                               : std::optional(bad(name, value, "no such format", "png, glb"));
    if (error) return error;
  }
  return std::nullopt;
}

RenderRequest defaults() {
  RenderRequest request;
  const auto rounded = [](const char* name) {
    return std::round(ShopperChoices::measure(name).reference * 1000.0) / 1000.0;
  };
  request.body = {rounded("stature"), rounded("bust"), rounded("waist"), rounded("hips")};
  request.skin = "cc9473";
  request.pose = "rest";
  request.outfit = {{"dress", "M", ShopperChoices::style("dress")->defaultColour}};
  request.light = "studio";
  return request;
}

// With a sex: the measured body's checks (a chart to size by, the rest pose) and its sex.
std::optional<ParameterError> measuredBody(RenderRequest& request, const std::map<std::string, std::string>& values,
                                           SizeNames& names) {
  const auto sex = values.find("sex");
  if (sex == values.end()) return std::nullopt;
  if (sex->second != "female" && sex->second != "male")
    return bad("sex", sex->second, "no such sex", "female, male (or none: the Mannequin)");
  if (!names.chart) return bad("sex", sex->second, "no size chart: measured bodies are off", "none");
  request.sex = sex->second;
  names.sex = request.sex == "male" ? Sex::Male : Sex::Female;
  if (names.chart->sizes(names.sex).empty())
    return bad("sex", sex->second, "the size chart has no sizes for it", "female, male");
  // The measured body's ranges are the size advice's: MakeHuman's reach, not the Mannequin's.
  names.ranges = BodyMeasuresText::ranges(*names.chart, names.sex);
  return std::nullopt;
}

// What a posed measured body cannot wear. Only a garment's own drape moves the body from
// rest into its pose (nodes/body/HumanBody.h): an outer layer meets it posed from the start,
// inside it, and bunches; a skirt or dress put on standing is passed through by the
// thighs of a sitting body.
std::optional<ParameterError> posedOutfit(const RenderRequest& request) {
  if (request.sex.empty() || request.pose == "rest") return std::nullopt;
  const std::string accepted =
      "rest with up to 3 garments; arms-down, arm-raised, walking with one; sitting with a tshirt or nothing";
  if (request.outfit.size() > 1) return bad("pose", request.pose, "a posed measured body wears one garment", accepted);
  if (request.pose == "sitting" && !request.outfit.empty() && request.outfit[0].style != "tshirt")
    return bad("pose", request.pose, "a sitting body's thighs pass through a " + request.outfit[0].style, accepted);
  return std::nullopt;
}

}  // namespace

std::variant<RenderRequest, ParameterError> RenderRequest::parse(const QueryParameters& parameters,
                                                                 const SizeChart* chart) {
  auto values = byName(parameters);
  if (auto* error = std::get_if<ParameterError>(&values)) return *error;
  const auto& named = std::get<std::map<std::string, std::string>>(values);
  RenderRequest request = defaults();
  SizeNames names;
  names.chart = named.count("sex") ? chart : nullptr;
  if (auto error = measuredBody(request, named, names)) return *error;
  if (auto error = fill(request, named, names)) return *error;
  if (auto error = posedOutfit(request)) return *error;
  if (request.format == "glb") {
    // A GLB holds meshes and colours: light, view and size leave it as it is, so they are
    // reset and every such request shares one canonical text (and ETag).
    const RenderRequest plain = defaults();
    request.light = plain.light;
    request.azimuth = plain.azimuth, request.elevation = plain.elevation;
    request.width = plain.width, request.height = plain.height;
    request.fitMap.clear();  // the garments in their own colours
  }
  return request;
}

std::vector<std::string> RenderRequest::parameterNames() {
  return {std::begin(kNames), std::end(kNames)};
}

std::variant<RenderRequest, ParameterError> RenderRequest::parseCanonical(const std::string& text,
                                                                          const SizeChart* chart) {
  return parse(RequestParameters::split(text), chart);
}

std::string RenderRequest::drapeKey() const {
  std::string text = formatted("stature=%.3f&bust=%.3f", body.stature, body.bust) +
                     formatted("&waist=%.3f&hips=%.3f", body.waist, body.hips) + sexText() + "&pose=" + pose +
                     "&outfit=";
  for (size_t i = 0; i < outfit.size(); ++i) text += (i ? "," : "") + outfit[i].style + ":" + outfit[i].size;
  return text;
}

std::string RenderRequest::sceneKey() const {
  std::string text = formatted("stature=%.3f&bust=%.3f", body.stature, body.bust) +
                     formatted("&waist=%.3f&hips=%.3f", body.waist, body.hips) + sexText() + "&skin=" + skin +
                     "&pose=" + pose + "&outfit=";
  for (size_t i = 0; i < outfit.size(); ++i)
    text += (i ? "," : "") + outfit[i].style + ":" + outfit[i].size + ":" + outfit[i].colour;
  if (outfit.empty()) text += "none";
  return text + "&light=" + light + (fitMap.empty() ? "" : "&fitmap=" + fitMap);
}

int RenderRequest::supersample() const {
  constexpr long kMostSamples = 4L * RequestLimits::kMaxPixels;
  int k = 3;
  while (k > 1 && long(k) * k * width * height > kMostSamples) --k;
  return k;
}

std::string RenderRequest::canonical() const {
  if (format == "glb") return sceneKey() + "&format=glb";
  return sceneKey() + formatted("&view=%.1f,%.1f", azimuth, elevation) + "&size=" + std::to_string(width) + "x" +
         std::to_string(height);
}

}  // namespace figment::serve

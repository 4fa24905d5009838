#include "serve/request/RenderRequest.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "io/GarmentCatalogue.h"
#include "serve/request/BodyMeasuresText.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/request/MeasuredPoses.h"
#include "serve/request/Utf8Text.h"
#include "sim/garment/GarmentStyle.h"

namespace figment::serve {

namespace {

const char* const kNames[] = {"stature", "bust", "chest", "waist",  "hips", "skin", "pose",   "outfit",
                              "light",   "view", "size",  "format", "body", "sex",  "fitmap", "underwear"};

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

// What the request's body decides: the styles and sizes an outfit item may name and the
// measurements' ranges. A made body's come from the garment catalogue and its chart
// (MadeBodyChoices), the Mannequin's from ShopperChoices.
struct BodyNames {
  const GarmentCatalogue* catalogue = nullptr;  // null: the Mannequin
  Sex sex = Sex::Female;
  std::vector<MeasureRange> ranges;  // a made body's: its sex's (what /api/fit accepts)
};

std::string acceptedItems(const BodyNames& names) {
  if (!names.catalogue)
    return "style[:rrggbb] (the paper's patterns as cut, no sizes), styles " + namesOf(ShopperChoices::styles());
  return "style:size[:rrggbb], " + std::string(sexName(names.sex)) + " styles " +
         MadeBodyChoices::styleNames(*names.catalogue, names.sex) + " (/api/catalogue lists each one's sizes)";
}

// The Mannequin's item: a pattern of ShopperChoices as cut, in a colour.
std::optional<ParameterError> mannequinItem(const std::string& value, const std::string& item,
                                            const std::string& accepted, OutfitItem& out) {
  const size_t a = item.find(':');
  out.style = item.substr(0, a);
  const GarmentStyle* style = ShopperChoices::style(out.style);
  if (!style) return bad("outfit", value, "no style named " + Utf8Text::shown(out.style, 32), accepted);
  out.size.clear();
  out.colour = a == std::string::npos ? style->defaultColour : lower(item.substr(a + 1));
  if (isHex6(out.colour)) return std::nullopt;
  if (item.find(':', a + 1) != std::string::npos || !out.colour.empty())
    return bad("outfit", value,
               "the Mannequin wears the paper's patterns as cut, in no sizes: " + Utf8Text::shown(item, 32), accepted);
  return bad("outfit", value, "not a colour: " + Utf8Text::shown(out.colour, 32), accepted);
}

// A made body's item: a catalogue style in one of its sizes for the body's sex (letter code
// or number, kept as the letter code), in a colour (the style's first without one).
std::optional<ParameterError> madeItem(const std::string& value, const std::string& item, const BodyNames& names,
                                       const std::string& accepted, OutfitItem& out) {
  const size_t a = item.find(':'), b = a == std::string::npos ? a : item.find(':', a + 1);
  if (a == std::string::npos)
    return bad("outfit", value, "a garment without a size: " + Utf8Text::shown(item, 32), accepted);
  out.style = item.substr(0, a);
  out.size = item.substr(a + 1, b == std::string::npos ? std::string::npos : b - a - 1);
  auto style = MadeBodyChoices::style(*names.catalogue, names.sex, out.style, "outfit", value);
  if (auto* error = std::get_if<ParameterError>(&style)) return error->accepted = accepted, *error;
  const CatalogueStyle& sold = *std::get<const CatalogueStyle*>(style);
  const int index = names.catalogue->chart().find(names.sex, out.size);
  const std::vector<std::string>& sizes = sold.sizes(names.sex);
  if (index >= 0) out.size = names.catalogue->chart().sizes(names.sex)[size_t(index)].name;
  if (index < 0 || std::find(sizes.begin(), sizes.end(), out.size) == sizes.end())
    return bad("outfit", value,
               "no " + std::string(sexName(names.sex)) + " size " + Utf8Text::shown(item.substr(a + 1, b - a - 1), 32) +
                   " of " + sold.name,
               "sizes " + namesOf(sizes));
  out.colour = b == std::string::npos ? sold.colours.front() : lower(item.substr(b + 1));
  if (!isHex6(out.colour)) return bad("outfit", value, "not a colour: " + Utf8Text::shown(out.colour, 32), accepted);
  return std::nullopt;
}

std::optional<ParameterError> outfitItem(const std::string& value, const std::string& item, const BodyNames& names,
                                         OutfitItem& out) {
  const std::string accepted = acceptedItems(names);
  return names.catalogue ? madeItem(value, item, names, accepted, out) : mannequinItem(value, item, accepted, out);
}

std::optional<ParameterError> outfit(const std::string& value, const BodyNames& names, std::vector<OutfitItem>& out) {
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

// A Mannequin's pose is one of ShopperChoices'; a made body's one of MakeHuman's rig presets.
std::optional<ParameterError> pose(const std::string& value, const BodyNames& names, std::string& out) {
  if (names.catalogue ? MeasuredPoses::find(value) != nullptr : ShopperChoices::pose(value) != nullptr)
    return out = value, std::nullopt;
  if (names.catalogue && ShopperChoices::pose(value))
    return bad("pose", value, "the made body has MakeHuman's rig, not the Mannequin's joints", MeasuredPoses::names());
  return bad("pose", value, "no such pose",
             names.catalogue ? MeasuredPoses::names() : namesOf(ShopperChoices::poses()));
}

// Stretch needs the drape alone; ease and pressure the skin as a mesh, which a made body
// has and the Mannequin (its skin drawn over collision volumes) has not.
std::optional<ParameterError> fitMap(const std::string& value, const BodyNames& names, std::string& out) {
  const std::string accepted = "stretch, ease, pressure, none (on body=mannequin stretch or none)";
  if (value == "stretch" || value == "none") return out = value == "none" ? "" : value, std::nullopt;
  if (value != "ease" && value != "pressure") return bad("fitmap", value, "no such fit map", accepted);
  if (!names.catalogue)
    return bad("fitmap", value, "ease and pressure need the made body, not the Mannequin", accepted);
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

// The made body's base layer (nodes/body/HumanBody.h), on unless turned off; the Mannequin
// is drawn as scanned, with none.
std::optional<ParameterError> underwear(const std::string& value, const BodyNames& names, bool& out) {
  if (!names.catalogue)
    return bad("underwear", value, "the Mannequin is drawn as scanned, without a base layer",
               "no underwear with body=mannequin");
  if (value != "on" && value != "off") return bad("underwear", value, "not on or off", "on (the default), off");
  out = value == "on";
  return std::nullopt;
}

std::optional<ParameterError> fill(RenderRequest& request, const std::map<std::string, std::string>& values,
                                   const BodyNames& names) {
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
    else if (name == "underwear")
      error = underwear(value, names, request.underwear);
    if (error) return error;
  }
  return std::nullopt;
}

// The body a request chooses (`body`, `sex`) and what that decides, before any other
// parameter is read: the made body by default, women's unless `sex` says otherwise.
std::optional<ParameterError> chooseBody(const std::map<std::string, std::string>& values,
                                         const GarmentCatalogue* catalogue, RenderRequest& request, BodyNames& names) {
  const auto body = values.find("body");
  const auto sex = values.find("sex");
  const std::string accepted = "made (the shopper's own body, the default), mannequin (the paper's scanned body)";
  if (body != values.end() && body->second != "made" && body->second != "mannequin")
    return bad("body", body->second, "no such body", accepted);
  if (body != values.end() && body->second == "mannequin") {
    if (sex != values.end())
      return bad("sex", sex->second, "the Mannequin is one scanned body: it has no sex to choose",
                 "no sex with body=mannequin");
    names.ranges = ShopperChoices::measures();
    return std::nullopt;
  }
  if (!catalogue) return bad("body", "made", "no garment catalogue: made bodies are off", "mannequin");
  request.sex = sex == values.end() ? "female" : sex->second;
  if (request.sex != "female" && request.sex != "male")
    return bad("sex", sex->second, "no such sex", "female, male (the made body's)");
  names.catalogue = catalogue;
  names.sex = request.sex == "male" ? Sex::Male : Sex::Female;
  if (MadeBodyChoices::styles(*catalogue, names.sex).empty())
    return bad("sex", request.sex, "the catalogue sells nothing in its sizes", "female, male");
  // The made body's ranges are the size advice's: MakeHuman's reach, not the Mannequin's.
  names.ranges = BodyMeasuresText::ranges(catalogue->chart(), names.sex);
  return std::nullopt;
}

// What the chosen body is and wears when the request does not say: a made body the chart's
// M of its sex in the first style sold to it; the Mannequin as scanned, in the dress.
void defaults(RenderRequest& request, const BodyNames& names) {
  if (names.catalogue) {
    request.body = MadeBodyChoices::defaultBody(*names.catalogue, names.sex);
    const auto [style, size] = MadeBodyChoices::defaultGarment(*names.catalogue, names.sex);
    request.outfit = {{style, size, names.catalogue->style(style)->colours.front()}};
  } else {
    const auto rounded = [](const char* name) {
      return std::round(ShopperChoices::measure(name).reference * 1000.0) / 1000.0;
    };
    request.body = {rounded("stature"), rounded("bust"), rounded("waist"), rounded("hips")};
    request.outfit = {{"dress", "", ShopperChoices::style("dress")->defaultColour}};
  }
  request.skin = "cc9473";
  request.pose = "rest";
  request.light = "studio";
}

// What a posed made body cannot wear. Only a garment's own drape moves the body from
// rest into its pose (nodes/body/HumanBody.h): an outer layer meets it posed from the start,
// inside it, and bunches; a skirt or dress put on standing is passed through by the
// thighs of a sitting body. A sewn garment's panels are placed round the standing body and
// sewn on it (sim/pattern/PatternPlacement.h), so it is worn standing.
std::optional<ParameterError> posedOutfit(const RenderRequest& request, const BodyNames& names) {
  if (request.sex.empty() || request.pose == "rest") return std::nullopt;
  const std::string accepted =
      "rest with up to 3 garments; arms-down, arm-raised, walking with one cut style; sitting with a tshirt or "
      "nothing";
  if (request.outfit.size() > 1) return bad("pose", request.pose, "a posed measured body wears one garment", accepted);
  for (const OutfitItem& item : request.outfit)
    if (const CatalogueStyle* style = names.catalogue->style(item.style); style && style->sewn())
      return bad("pose", request.pose, item.style + " is sewn from a pattern on the standing body", accepted);
  if (request.pose == "sitting" && !request.outfit.empty() && request.outfit[0].style != "tshirt")
    return bad("pose", request.pose, "a sitting body's thighs pass through a " + request.outfit[0].style, accepted);
  return std::nullopt;
}

}  // namespace

std::variant<RenderRequest, ParameterError> RenderRequest::parse(const QueryParameters& parameters,
                                                                 const GarmentCatalogue* catalogue) {
  auto values = byName(parameters);
  if (auto* error = std::get_if<ParameterError>(&values)) return *error;
  const auto& named = std::get<std::map<std::string, std::string>>(values);
  RenderRequest request;
  BodyNames names;
  if (auto error = chooseBody(named, catalogue, request, names)) return *error;
  defaults(request, names);
  if (auto error = fill(request, named, names)) return *error;
  if (auto error = posedOutfit(request, names)) return *error;
  if (request.format == "glb") {
    // A GLB holds meshes and colours: light, view and size leave it as it is, so they are
    // reset and every such request shares one canonical text (and ETag).
    const RenderRequest plain;
    request.light = "studio";
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
                                                                          const GarmentCatalogue* catalogue) {
  return parse(RequestParameters::split(text), catalogue);
}

std::string RenderRequest::drapeKey() const {
  std::string text = formatted("stature=%.3f&bust=%.3f", body.stature, body.bust) +
                     formatted("&waist=%.3f&hips=%.3f", body.waist, body.hips) + bodyText() + "&pose=" + pose +
                     "&outfit=";
  for (size_t i = 0; i < outfit.size(); ++i)
    text += (i ? "," : "") + outfit[i].style + (outfit[i].size.empty() ? "" : ":" + outfit[i].size);
  if (outfit.empty()) text += "none";
  return text;
}

std::string RenderRequest::sceneKey() const {
  std::string text = formatted("stature=%.3f&bust=%.3f", body.stature, body.bust) +
                     formatted("&waist=%.3f&hips=%.3f", body.waist, body.hips) + bodyText() + "&skin=" + skin +
                     (underwear || mannequin() ? "" : "&underwear=off") + "&pose=" + pose + "&outfit=";
  for (size_t i = 0; i < outfit.size(); ++i)
    text += (i ? "," : "") + outfit[i].style + (outfit[i].size.empty() ? "" : ":" + outfit[i].size) + ":" +
            outfit[i].colour;
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

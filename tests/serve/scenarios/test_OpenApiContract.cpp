// serve/http/openapi.json (as figment-serve embeds it) says what the server takes, checked here
// against the server's own constants, lists and parser, so that no bound can drift from
// the code: each measurement's range on the Mannequin (ShopperChoices) and on a made body of
// each sex (the size advice's ranges of the shipped size chart), the parameters' names, every
// enumeration, the limits, and each pattern against the parser itself: over values at and
// past each edge, a pattern matches exactly those the parser takes, but for the rules it
// cannot state (written in its description), which these values break on purpose.
// scripts/openapi-choices.py writes the values that come from scenes/ (chart, catalogue).
// tests/serve/scenarios/test_contract.py then runs Schemathesis against a live server.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "serve/http/WebAssets.h"
#include "serve/request/BodyMeasuresText.h"
#include "serve/request/FitRequest.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/request/MeasuredPoses.h"
#include "serve/request/RenderRequest.h"
#include "serve/request/ShopperChoices.h"
#include "serve/workers/Digest.h"
#include "sim/garment/GarmentStyle.h"
#include "support/ShippedCatalogue.h"

using namespace figment::serve;
using nlohmann::json;

namespace {

const json& document() {
  static const json parsed = json::parse(findWebAsset("/openapi.json")->content);
  return parsed;
}

// The parameter `name` of the operation at `path` (GET), its $ref resolved.
const json& parameter(const std::string& path, const std::string& name) {
  for (const json& item : document()["paths"][path]["get"]["parameters"]) {
    const std::string ref = item.value("$ref", "");
    const json& resolved = ref.empty() ? item : document()["components"]["parameters"][ref.substr(ref.rfind('/') + 1)];
    if (resolved["name"] == name) return resolved;
  }
  throw std::runtime_error("no parameter " + name + " of " + path);
}

const json& render(const std::string& name) {
  return parameter("/api/render", name);
}

const figment::GarmentCatalogue& shipped() {
  return figment::test::shippedCatalogue();
}

const char* const kConditions[] = {"mannequin", "female", "male"};  // x-figment-by-body's keys

// Whether a render of `name`=`value` is taken on the Mannequin or a made body of `body`'s
// sex. A pose is asked in a tshirt: a sitting made body wears nothing else (a rule between
// them).
bool takes(const std::string& body, const std::string& name, const std::string& value) {
  QueryParameters parameters = {{name, value}};
  parameters.push_back(body == "mannequin" ? QueryParameters::value_type{"body", "mannequin"}
                                           : QueryParameters::value_type{"sex", body});
  if (name == "pose") parameters.push_back({"outfit", body == "mannequin" ? "tshirt" : "tshirt:M"});
  return std::holds_alternative<RenderRequest>(RenderRequest::parse(parameters, &shipped()));
}

MeasureRange rangeFor(const std::string& body, const std::string& name) {
  if (body == "mannequin") return ShopperChoices::measure(name);
  for (const MeasureRange& range :
       BodyMeasuresText::ranges(shipped().chart(), body == "male" ? figment::Sex::Male : figment::Sex::Female))
    if (range.name == name) return range;
  throw std::runtime_error("no range " + name);
}

std::string metres(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", value);
  return text;
}

std::set<std::string> strings(const json& list) {
  return list.get<std::set<std::string>>();
}

bool matches(const json& schemaOrRule, const std::string& value) {
  return std::regex_match(value, std::regex(schemaOrRule["pattern"].get<std::string>()));
}

}  // namespace

// The names of the GET parameters of the operation at `path`.
std::set<std::string> namesOf(const std::string& path) {
  std::set<std::string> names;
  for (const json& item : document()["paths"][path]["get"]["parameters"]) {
    const std::string ref = item["$ref"];
    names.insert(document()["components"]["parameters"][ref.substr(ref.rfind('/') + 1)]["name"].get<std::string>());
  }
  return names;
}

TEST(OpenApiContract, RenderParametersAreTheParsersOwn) {
  const std::set<std::string> listed = namesOf("/api/render"), fit = namesOf("/api/fit");
  const std::vector<std::string> renderNames = RenderRequest::parameterNames(), fitNames = FitRequest::parameterNames();
  EXPECT_EQ(listed, std::set<std::string>(renderNames.begin(), renderNames.end()));
  EXPECT_EQ(fit, std::set<std::string>(fitNames.begin(), fitNames.end()));
  // POST's form takes the same parameters as its query.
  const json& form = document()["paths"]["/api/render"]["post"]["requestBody"]["content"]
                               ["application/x-www-form-urlencoded"]["schema"];
  EXPECT_EQ(form["additionalProperties"], false);
  std::set<std::string> formNames;
  for (const auto& [name, schema] : form["properties"].items()) {
    formNames.insert(name);
    EXPECT_EQ(schema, render(name)["schema"]) << name;  // the query's schema, not another
  }
  EXPECT_EQ(formNames, listed);
}

TEST(OpenApiContract, EachMeasurementsRangeIsTheServersForEachSex) {
  for (const std::string name : {"stature", "bust", "chest", "waist", "hips"}) {
    const std::string measure = name == "chest" ? "bust" : name;
    const json& documented = render(name);
    double lowest = INFINITY, highest = -INFINITY;
    for (const std::string sex : kConditions) {
      const MeasureRange range = rangeFor(sex, measure);
      const json& rule = documented["x-figment-by-body"][sex];
      EXPECT_EQ(rule["minimum"].get<double>(), range.minimum) << name << " " << sex;
      EXPECT_EQ(rule["maximum"].get<double>(), range.maximum) << name << " " << sex;
      // The parser at each end, and a millimetre past it.
      EXPECT_TRUE(takes(sex, name, metres(range.minimum)) && takes(sex, name, metres(range.maximum))) << name << sex;
      EXPECT_FALSE(takes(sex, name, metres(range.minimum - 0.001))) << name << " " << sex;
      EXPECT_FALSE(takes(sex, name, metres(range.maximum + 0.001))) << name << " " << sex;
      lowest = std::min(lowest, range.minimum), highest = std::max(highest, range.maximum);
    }
    EXPECT_EQ(documented["schema"]["minimum"].get<double>(), lowest) << name;  // the schema: any of them
    EXPECT_EQ(documented["schema"]["maximum"].get<double>(), highest) << name;
    if (name != "chest") {  // the made woman's M, as a request without measurements is
      const BodyMeasures woman = MadeBodyChoices::defaultBody(shipped(), figment::Sex::Female);
      const std::map<std::string, double> defaults = {
          {"stature", woman.stature}, {"bust", woman.bust}, {"waist", woman.waist}, {"hips", woman.hips}};
      EXPECT_EQ(documented["schema"]["default"].get<double>(), defaults.at(measure)) << name;
    }
  }
}

TEST(OpenApiContract, EachFitMeasurementsRangeIsTheServersForEachSex) {
  for (const std::string name : {"stature", "bust", "waist", "hips"}) {
    const json& documented = parameter("/api/fit", name);
    EXPECT_TRUE(documented["required"].get<bool>()) << name;
    double lowest = INFINITY, highest = -INFINITY;
    for (const std::string sex : {"female", "male"}) {
      const MeasureRange range = rangeFor(sex, name);
      EXPECT_EQ(documented["x-figment-by-sex"][sex]["minimum"].get<double>(), range.minimum) << name << " " << sex;
      EXPECT_EQ(documented["x-figment-by-sex"][sex]["maximum"].get<double>(), range.maximum) << name << " " << sex;
      lowest = std::min(lowest, range.minimum), highest = std::max(highest, range.maximum);
    }
    EXPECT_EQ(documented["schema"]["minimum"].get<double>(), lowest) << name;
    EXPECT_EQ(documented["schema"]["maximum"].get<double>(), highest) << name;
  }
}

TEST(OpenApiContract, EnumerationsAreTheShopperChoicesLists) {
  std::set<std::string> tones, lights, poses, rigPoses, styles;
  for (const NamedColour& tone : ShopperChoices::skinTones()) tones.insert(tone.name);
  for (const LightPreset& light : ShopperChoices::lights()) lights.insert(light.name);
  for (const Pose& pose : ShopperChoices::poses()) poses.insert(pose.name);
  for (const MeasuredPose& pose : MeasuredPoses::all()) rigPoses.insert(pose.name);
  for (const figment::Sex sex : {figment::Sex::Female, figment::Sex::Male})
    for (const figment::CatalogueStyle* style : MadeBodyChoices::styles(shipped(), sex)) styles.insert(style->name);
  EXPECT_EQ(strings(render("skin")["schema"]["anyOf"][0]["enum"]), tones);
  EXPECT_EQ(strings(render("light")["schema"]["enum"]), lights);
  EXPECT_EQ(strings(render("pose")["x-figment-by-body"]["mannequin"]["enum"]), poses);
  for (const char* sex : {"female", "male"})
    EXPECT_EQ(strings(render("pose")["x-figment-by-body"][sex]["enum"]), rigPoses);
  std::set<std::string> anyPose = poses;
  anyPose.insert(rigPoses.begin(), rigPoses.end());
  EXPECT_EQ(strings(render("pose")["schema"]["enum"]), anyPose);
  EXPECT_EQ(strings(render("sex")["schema"]["enum"]), (std::set<std::string>{"female", "male"}));
  EXPECT_EQ(strings(render("body")["schema"]["enum"]), (std::set<std::string>{"made", "mannequin"}));
  EXPECT_EQ(strings(parameter("/api/fit", "sex")["schema"]["enum"]), (std::set<std::string>{"female", "male"}));
  EXPECT_EQ(strings(parameter("/api/fit", "style")["schema"]["enum"]), styles);
  for (const figment::Sex sex : {figment::Sex::Female, figment::Sex::Male}) {
    std::set<std::string> sold;
    for (const figment::CatalogueStyle* style : MadeBodyChoices::styles(shipped(), sex)) sold.insert(style->name);
    EXPECT_EQ(strings(parameter("/api/fit", "style")["x-figment-by-sex"][figment::sexName(sex)]["enum"]), sold);
  }
}

TEST(OpenApiContract, EachEnumeratedValueIsTakenAndNoOther) {
  for (const std::string name : {"skin", "light", "pose", "fitmap", "format", "underwear"})
    for (const std::string sex : kConditions) {
      const json& documented = render(name);
      const json& values = documented.contains("x-figment-by-body") ? documented["x-figment-by-body"][sex]["enum"]
                           : name == "skin"                         ? documented["schema"]["anyOf"][0]["enum"]
                                                                    : documented["schema"]["enum"];
      for (const std::string value : values) EXPECT_TRUE(takes(sex, name, value)) << name << "=" << value << " " << sex;
      for (const std::string& value : strings(documented["schema"].value("enum", json::array())))
        EXPECT_EQ(takes(sex, name, value), strings(values).count(value) == 1) << name << "=" << value << " " << sex;
      for (const std::string other : {"", "Rest", "STUDIO", "FAIR", "#medium", "none2", "png "})
        if (!strings(values).count(other)) {
          EXPECT_FALSE(takes(sex, name, other)) << name << "=" << other << " " << sex;
        }
    }
}

TEST(OpenApiContract, TheOutfitPatternTakesWhatTheParserTakes) {
  const std::vector<std::string> styles = {"dress", "skirt", "tshirt", "pencil", "tee", "cape", "Dress"};
  std::vector<std::string> sizes = {"XXXL", "m", "30", "33", "3XL", "64", ""};
  for (const figment::Sex sex : {figment::Sex::Female, figment::Sex::Male})
    for (const figment::ChartSize& size : shipped().chart().sizes(sex)) {
      sizes.push_back(size.name);
      sizes.push_back(size.number);
    }
  std::vector<std::string> values = {"",
                                     "none",
                                     "None",
                                     "dress",
                                     "dress:",
                                     "dress:M,",
                                     ",dress:M",
                                     "dress:M:ff0000:00",
                                     "tshirt:M,skirt:L",
                                     "tshirt:M,skirt:L:00FF00,dress:S",
                                     "tshirt:M,skirt:L,dress:S,pencil:M",
                                     "dress:1f40b3",
                                     "skirt:00FF00,tshirt",
                                     "dress::1f40b3"};
  for (const std::string& style : styles)
    for (const std::string& size : sizes)
      for (const std::string colour : {"", ":1f40b3", ":1F40B3", ":1f40b", ":1f40bz"})
        values.push_back(style + ":" + size + colour);
  for (const std::string sex : kConditions)
    for (const std::string& value : values)
      EXPECT_EQ(matches(render("outfit")["x-figment-by-body"][sex], value), takes(sex, "outfit", value))
          << "outfit=" << value << " " << sex;
  // The union's pattern takes each sex's, and a style worn twice is the rule it cannot state.
  for (const std::string& value : values)
    if (takes("mannequin", "outfit", value) || takes("female", "outfit", value) || takes("male", "outfit", value)) {
      EXPECT_TRUE(matches(render("outfit")["schema"], value)) << value;
    }
  EXPECT_TRUE(matches(render("outfit")["schema"], "dress:M,dress:S"));
  EXPECT_FALSE(takes("female", "outfit", "dress:M,dress:S"));
  // No body wears a mix of bodies' items (Schemathesis sent "sundress:L,skirt:47AE40", a made
  // body's item and the Mannequin's, which the per-item union let through), nor does the union.
  for (const std::string value : {"sundress:L,skirt:47AE40", "skirt,dress:M", "tshirt:56,dress:M", "dress:M,skirt"}) {
    for (const std::string sex : kConditions) EXPECT_FALSE(takes(sex, "outfit", value)) << value << " " << sex;
    EXPECT_FALSE(matches(render("outfit")["schema"], value)) << value;
  }
  // The styles sewn from patterns, which a posed made body refuses (the contract's hooks keep
  // the rule): the catalogue's.
  std::set<std::string> sewn;
  for (const figment::CatalogueStyle& style : shipped().styles())
    if (style.sewn()) sewn.insert(style.name);
  EXPECT_FALSE(sewn.empty());
  EXPECT_EQ(strings(render("outfit")["x-figment-sewn-styles"]), sewn);
}

TEST(OpenApiContract, TheViewPatternTakesWhatTheParserTakes) {
  for (const std::string value :
       {"0,0",     "360,80",   "-360,-60", "360.0,80.000", "360.1,0",        "-360.5,0",
        "0,80.01", "0,-60.01", "361,0",    "0,81",         "0,-61",          ".5,.5",
        "-.5,-.5", "5.,5.",    "00360,0",  "0360.,-060.",  "359.999,79.999", "12.3456789,-45.6",
        "1e2,0",   "+5,0",     "inf,0",    "nan,0",        "0,0,0",          "0",
        "0,",      ",0",       "-,0",      ".,0",          "0, 0",           " 0,0",
        "0x1,0",   "front",    "back",     "left",         "right",          "Front",
        "up",      "",         "-0,-0"})
    EXPECT_EQ(matches(render("view")["schema"], value), takes("mannequin", "view", value)) << "view=" << value;
}

TEST(OpenApiContract, TheSizePatternTakesWhatTheParserTakesBarThePixelsInAll) {
  const json& size = render("size");
  EXPECT_EQ(size["x-figment-max-pixels"].get<int>(), RequestLimits::kMaxPixels);
  const std::string low = std::to_string(RequestLimits::kMinSide), high = std::to_string(RequestLimits::kMaxSide);
  const std::string under = std::to_string(RequestLimits::kMinSide - 1),
                    over = std::to_string(RequestLimits::kMaxSide + 1);
  for (const std::string& value :
       {low + "x" + low,          under + "x" + low,        low + "x" + under,        high + "x" + low,
        low + "x" + high,         over + "x" + low,         low + "x" + over,         std::string("1600x1200"),
        std::string("1200x1600"), std::string("1600x1201"), std::string("1600x1600"), std::string("0064x0064"),
        std::string("00064x064"), std::string("000064x64"), std::string("64X64"),     std::string("64x"),
        std::string("x64"),       std::string("-64x64"),    std::string("+64x64"),    std::string("800x600"),
        std::string("100000x1"),  std::string("64x64 "),    std::string("64x64x64")}) {
    const bool shape = matches(size["schema"], value) && int(value.size()) <= size["schema"]["maxLength"].get<int>();
    const bool withinPixels = shape && std::stol(value) * std::stol(value.substr(value.find('x') + 1)) <=
                                           size["x-figment-max-pixels"].get<long>();
    EXPECT_EQ(shape && withinPixels, takes("mannequin", "size", value)) << "size=" << value;
  }
}

TEST(OpenApiContract, TheSkinPatternTakesHexAsTheParserDoes) {
  for (const std::string value : {"aabbcc", "AABBCC", "#aabbcc", "#AaBbCc", "aabbc", "aabbccd", "#aabbccd", "gggggg",
                                  "##aabbcc", "", "#", "medium", "#medium", "MEDIUM"}) {
    const json& schema = render("skin")["schema"];
    const bool documented = strings(schema["anyOf"][0]["enum"]).count(value) || matches(schema["anyOf"][1], value);
    EXPECT_EQ(documented, takes("mannequin", "skin", value)) << "skin=" << value;
  }
}

TEST(OpenApiContract, AJobIdIsAnEtagsDigits) {
  const json& id = document()["paths"]["/api/jobs/{id}"]["get"]["parameters"][0];
  EXPECT_TRUE(matches(id["schema"], Digest().add("a request").hex()));
  EXPECT_FALSE(matches(id["schema"], "0"));
}

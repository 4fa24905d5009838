// A render request's parameters: defaults (the made body, the chart's M, in the first style
// sold to it), canonical text that reads back to itself, the Mannequin as an explicit choice,
// and every class of bad parameter refused with the parameter, its value and what is
// accepted. Checked against the shipped garment catalogue, as the server checks them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "serve/request/RenderRequest.h"
#include "support/ShippedCatalogue.h"

using namespace figment;
using namespace figment::serve;

namespace {

const GarmentCatalogue* catalogue() {
  return &test::shippedCatalogue();
}

std::variant<RenderRequest, ParameterError> parse(const QueryParameters& parameters) {
  return RenderRequest::parse(parameters, catalogue());
}

RenderRequest ok(const QueryParameters& parameters) {
  auto parsed = parse(parameters);
  if (auto* error = std::get_if<ParameterError>(&parsed)) ADD_FAILURE() << error->parameter << ": " << error->error;
  return std::holds_alternative<RenderRequest>(parsed) ? std::get<RenderRequest>(parsed) : RenderRequest{};
}

ParameterError refused(const QueryParameters& parameters, const GarmentCatalogue* given = catalogue()) {
  auto parsed = RenderRequest::parse(parameters, given);
  EXPECT_TRUE(std::holds_alternative<ParameterError>(parsed)) << "accepted";
  return std::holds_alternative<ParameterError>(parsed) ? std::get<ParameterError>(parsed) : ParameterError{};
}

// `parameters` on the Mannequin.
QueryParameters mannequin(QueryParameters parameters) {
  parameters.emplace_back("body", "mannequin");
  return parameters;
}

}  // namespace

TEST(RenderRequest, NoParametersIsTheMadeWomansMInTheDress) {
  const RenderRequest request = ok({});
  EXPECT_FALSE(request.mannequin());
  EXPECT_EQ(request.canonical(),
            "stature=1.680&bust=0.880&waist=0.720&hips=0.960&sex=female&skin=cc9473&pose=rest&outfit=dress:M:1f40b3"
            "&light=studio&view=0.0,0.0&size=800x600");
  // A man's default is the men's M in the first style sold to men.
  const RenderRequest man = ok({{"sex", "male"}});
  EXPECT_EQ(man.canonical(),
            "stature=1.740&bust=0.960&waist=0.840&hips=1.000&sex=male&skin=cc9473&pose=rest&outfit=tshirt:M:d9d9d1"
            "&light=studio&view=0.0,0.0&size=800x600");
  // The Mannequin as scanned, in the paper's dress as cut.
  EXPECT_EQ(ok(mannequin({})).canonical(),
            "stature=1.659&bust=0.891&waist=0.696&hips=0.939&body=mannequin&skin=cc9473&pose=rest&outfit=dress:1f40b3"
            "&light=studio&view=0.0,0.0&size=800x600");
}

TEST(RenderRequest, CanonicalTextReadsBackToItself) {
  const RenderRequest request = ok({{"stature", "1.7204"},
                                    {"chest", "0.95"},
                                    {"skin", "tan"},
                                    {"outfit", "tshirt:L:2E7D32,skirt:36"},
                                    {"view", "-30,10.04"},
                                    {"size", "320x240"},
                                    {"light", "warm"},
                                    {"pose", "rest"}});
  EXPECT_EQ(request.canonical(),
            "stature=1.720&bust=0.950&waist=0.720&hips=0.960&sex=female&skin=a86b45&pose=rest"
            "&outfit=tshirt:L:2e7d32,skirt:S:8c1f33&light=warm&view=330.0,10.0&size=320x240");
  const RenderRequest scanned = ok(mannequin({{"outfit", "tshirt:2E7D32,skirt"}, {"pose", "relaxed"}}));
  EXPECT_EQ(scanned.canonical(),
            "stature=1.659&bust=0.891&waist=0.696&hips=0.939&body=mannequin&skin=cc9473&pose=relaxed"
            "&outfit=tshirt:2e7d32,skirt:8c1f33&light=studio&view=0.0,0.0&size=800x600");
  for (const RenderRequest& one : {request, scanned}) {
    auto again = RenderRequest::parseCanonical(one.canonical(), catalogue());
    ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
    EXPECT_EQ(std::get<RenderRequest>(again).canonical(), one.canonical());
  }
}

TEST(RenderRequest, ColoursLightAndViewShareTheDrape) {
  const RenderRequest a = ok({{"outfit", "dress:M:111111"}, {"view", "back"}, {"light", "soft"}});
  const RenderRequest b = ok({{"outfit", "dress:M:222222"}});
  EXPECT_EQ(a.drapeKey(), b.drapeKey());
  EXPECT_NE(a.canonical(), b.canonical());
  EXPECT_NE(ok({{"outfit", "dress:L"}}).drapeKey(), b.drapeKey());  // the control: a size drapes anew
  EXPECT_NE(ok(mannequin({{"outfit", "dress"}})).drapeKey(), ok({{"outfit", "dress:M"}}).drapeKey());
}

TEST(RenderRequest, EveryClassOfBadParameterNamesItsParameterValueAndRange) {
  struct Case {
    QueryParameters parameters;
    std::string parameter, error;
  };
  const std::vector<Case> cases = {
      {{{"stature", "tall"}}, "stature", "not a number"},
      {{{"stature", "170"}}, "stature", "out of range"},
      {{{"waist", "nan"}}, "waist", "not a number"},
      {{{"bust", "0.9"}, {"chest", "1.0"}}, "chest", "bust and chest differ"},
      {{{"skin", "green"}}, "skin", "not a skin tone"},
      {{{"pose", "../../etc"}}, "pose", "no such pose"},
      {{{"light", "laser"}}, "light", "no such light"},
      {{{"outfit", "cape:M"}}, "outfit", "no style named cape"},
      {{{"outfit", "dress:9XL"}}, "outfit", "no female size 9XL of dress"},
      {{{"outfit", "dress"}}, "outfit", "a garment without a size: dress"},
      {{{"outfit", "dress:M:blue"}}, "outfit", "not a colour: blue"},
      {{{"outfit", "dress:M,dress:L"}}, "outfit", "a style worn twice: dress"},
      {{{"outfit", "tshirt:M,skirt:M,dress:M,tshirt:S"}}, "outfit", "too many garments"},
      {{{"view", "sideways"}}, "view", "not a view"},
      {{{"view", "0,90"}}, "view", "out of range"},
      {{{"size", "800"}}, "size", "not a size"},
      {{{"size", "4000x3000"}}, "size", "too small or too large"},
      {{{"size", "1600x1600"}}, "size", "too small or too large"},
      {{{"file", "/etc/passwd"}}, "file", "unknown parameter"},
      {{{"body", "robot"}}, "body", "no such body"},
      {{{"sex", "x"}}, "sex", "no such sex"},
      {{{"body", "mannequin"}, {"sex", "female"}}, "sex", "the Mannequin is one scanned body: it has no sex to choose"},
      {{{"body", "mannequin"}, {"outfit", "dress:M"}},
       "outfit",
       "the Mannequin wears the paper's patterns as cut, in no sizes: dress:M"},
      {{{"body", "mannequin"}, {"outfit", "pencil"}}, "outfit", "no style named pencil"},
      {{{"pose", "rest"}, {"pose", "rest"}}, "pose", "given twice"},
      {{{"skin", std::string(300, 'a')}}, "skin", "value too long"},
  };
  for (const Case& c : cases) {
    const ParameterError error = refused(c.parameters);
    EXPECT_EQ(error.parameter, c.parameter) << c.error;
    EXPECT_EQ(error.error, c.error) << c.parameter;
    EXPECT_FALSE(error.accepted.empty()) << c.parameter;
    EXPECT_LE(error.value.size(), 64u);
  }
}

TEST(RenderRequest, TheBodyAloneIsAnEmptyOutfit) {
  EXPECT_TRUE(ok({{"outfit", "none"}}).outfit.empty());
  EXPECT_TRUE(ok({{"outfit", ""}}).outfit.empty());
}

TEST(RenderRequest, AGlbIgnoresLightViewAndSize) {
  const RenderRequest a = ok({{"format", "glb"}, {"light", "warm"}, {"view", "back"}, {"size", "320x240"}});
  const RenderRequest b = ok({{"format", "glb"}});
  EXPECT_EQ(a.canonical(), b.canonical());
  EXPECT_NE(a.canonical(), ok({}).canonical());  // the control: a PNG is another thing
  EXPECT_EQ(refused({{"format", "obj"}}).parameter, "format");
}

TEST(RenderRequest, TheMadeBodysSizesAreTheCataloguesForItsSex) {
  const RenderRequest request = ok({{"outfit", "pencil:38:FF0000"}});
  EXPECT_EQ(request.sex, "female");
  ASSERT_EQ(request.outfit.size(), 1u);
  EXPECT_EQ(request.outfit[0].size, "M");  // the chart's number, named by its letter code
  EXPECT_NE(request.drapeKey().find("sex=female"), std::string::npos);
  EXPECT_EQ(ok({{"sex", "male"}, {"outfit", "tshirt:XXL"}}).outfit[0].size, "XXL");  // a men's size
  // Every style and size the catalogue sells to a sex parses, and nothing else does.
  for (const Sex sex : {Sex::Female, Sex::Male})
    for (const CatalogueStyle& style : catalogue()->styles())
      for (const ChartSize& size : catalogue()->chart().sizes(sex)) {
        const std::vector<std::string>& sold = style.sizes(sex);
        const bool sells = std::find(sold.begin(), sold.end(), size.name) != sold.end();
        auto parsed = parse({{"sex", sexName(sex)}, {"outfit", style.name + ":" + size.name}});
        EXPECT_EQ(std::holds_alternative<RenderRequest>(parsed), sells) << style.name << ":" << size.name;
      }
}

TEST(RenderRequest, AMadeBodyRefusesWhatItCannotWear) {
  EXPECT_EQ(refused({}, nullptr).error, "no garment catalogue: made bodies are off");
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(RenderRequest::parse(mannequin({}), nullptr)));
  // The Mannequin's joints are not MakeHuman's rig: its poses are refused, naming the rig's.
  const ParameterError relaxed = refused({{"pose", "relaxed"}});
  EXPECT_EQ(relaxed.parameter, "pose");
  EXPECT_EQ(relaxed.accepted, "rest, arms-down, arm-raised, walking, sitting");
  EXPECT_EQ(refused(mannequin({{"pose", "sitting"}})).parameter, "pose");  // and the rig's for the Mannequin
  EXPECT_EQ(refused({{"sex", "male"}, {"outfit", "dress:M"}}).error, "dress is not sold in male sizes");
  // A sewn garment is placed and sewn round the standing body: worn at rest, not posed.
  EXPECT_EQ(ok({{"outfit", "tee:M"}}).outfit[0].style, "tee");
  EXPECT_EQ(ok({{"outfit", "tshirt:M,sundress:L"}}).outfit[1].style, "sundress");  // as an outer layer too
  const ParameterError posed = refused({{"outfit", "tee:M"}, {"pose", "walking"}});
  EXPECT_EQ(posed.parameter, "pose");
  EXPECT_EQ(posed.error, "tee is sewn from a pattern on the standing body");
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parse({{"outfit", "tshirt:M"}, {"pose", "walking"}})));
}

TEST(RenderRequest, AMadeBodysMeasurementsTakeTheSizeAdvicesRanges) {
  // MakeHuman's reach, as GET /api/fit accepts it: the chart's bodies widened by 8 cm each
  // side and stature 1.45 to 1.95; not the Mannequin's ranges.
  const std::vector<ChartSize>& women = catalogue()->chart().sizes(Sex::Female);
  char over[16], accepted[64];
  std::snprintf(over, sizeof over, "%.2f", women.back().bust + 0.10);
  std::snprintf(accepted, sizeof accepted, "%.2f to %.2f (metres)", women.front().bust - 0.08,
                women.back().bust + 0.08);
  const ParameterError bust = refused({{"bust", over}});
  EXPECT_EQ(bust.parameter, "bust");
  EXPECT_EQ(bust.value, over);
  EXPECT_EQ(bust.accepted, accepted);
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parse({{"stature", "1.93"}})));
  EXPECT_EQ(refused(mannequin({{"stature", "1.93"}})).parameter, "stature");  // the Mannequin's range
  EXPECT_EQ(refused({{"chest", "0.60"}}).parameter, "chest");
}

TEST(RenderRequest, APosedMadeBodyWearsOneGarmentAndSitsOnlyInATshirt) {
  for (const char* pose : {"rest", "arms-down", "arm-raised", "walking", "sitting"}) {
    auto one = parse({{"pose", pose}, {"outfit", "tshirt:M"}});
    ASSERT_TRUE(std::holds_alternative<RenderRequest>(one)) << pose;
    EXPECT_EQ(std::get<RenderRequest>(one).pose, pose);
    EXPECT_NE(std::get<RenderRequest>(one).drapeKey().find(std::string("pose=") + pose), std::string::npos);
  }
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parse({{"outfit", "tshirt:M,pencil:M"}})));
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parse({{"pose", "sitting"}, {"outfit", ""}})));
  for (const auto& [pose, outfit] : std::vector<std::pair<std::string, std::string>>{
           {"walking", "tshirt:M,pencil:M"}, {"arms-down", "pencil:S,tshirt:M"}, {"sitting", "pencil:M"}}) {
    auto refusal = parse({{"pose", pose}, {"outfit", outfit}});
    ASSERT_TRUE(std::holds_alternative<ParameterError>(refusal)) << pose << " " << outfit;
    EXPECT_EQ(std::get<ParameterError>(refusal).parameter, "pose");
    EXPECT_EQ(std::get<ParameterError>(refusal).value, pose);
    EXPECT_NE(std::get<ParameterError>(refusal).accepted.find("sitting with a tshirt"), std::string::npos);
  }
}

TEST(RenderRequest, PicturesAreSupersampledWithinABoundOnTheDrawnPixels) {
  EXPECT_EQ(ok({}).supersample(), 3);  // the default picture: figment-view's
  EXPECT_EQ(ok({{"size", "64x64"}}).supersample(), 3);
  EXPECT_EQ(ok({{"size", "1600x1200"}}).supersample(), 2);  // the largest
  for (const char* size : {"1600x1000", "1200x1600", "1100x1100", "64x1600"}) {
    const RenderRequest request = ok({{"size", size}});
    const long k = request.supersample(), pixels = long(request.width) * request.height;
    EXPECT_GE(k, 1) << size;
    EXPECT_LE(k * k * pixels, 4L * RequestLimits::kMaxPixels) << size;
    if (k < 3) {
      EXPECT_GT((k + 1) * (k + 1) * pixels, 4L * RequestLimits::kMaxPixels) << size;
    }
  }
}

TEST(RenderRequest, AFitMapIsPartOfTheSceneButNotOfTheDrape) {
  const RenderRequest plain = ok({{"outfit", "tshirt:S"}});
  const RenderRequest mapped = ok({{"outfit", "tshirt:S"}, {"fitmap", "stretch"}});
  EXPECT_EQ(mapped.fitMap, "stretch");
  EXPECT_EQ(mapped.drapeKey(), plain.drapeKey());  // the same drape, coloured otherwise
  EXPECT_NE(mapped.sceneKey(), plain.sceneKey());
  EXPECT_NE(mapped.canonical().find("&fitmap=stretch"), std::string::npos);  // so another ETag
  EXPECT_EQ(ok({{"outfit", "tshirt:S"}, {"fitmap", "none"}}).canonical(), plain.canonical());
  EXPECT_EQ(plain.canonical().find("fitmap"), std::string::npos);  // earlier requests' tags unchanged
  auto again = RenderRequest::parseCanonical(mapped.canonical(), catalogue());
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
  EXPECT_EQ(std::get<RenderRequest>(again).canonical(), mapped.canonical());
  EXPECT_EQ(ok({{"fitmap", "stretch"}, {"format", "glb"}}).canonical(), ok({{"format", "glb"}}).canonical());
  const ParameterError bad = refused({{"fitmap", "heat"}});
  EXPECT_EQ(bad.parameter, "fitmap");
  EXPECT_EQ(bad.accepted, "stretch, ease, pressure, none (on body=mannequin stretch or none)");
  // Ease and pressure measure from the skin as a mesh: a made body's, not the Mannequin's.
  EXPECT_EQ(refused(mannequin({{"fitmap", "ease"}})).error, "ease and pressure need the made body, not the Mannequin");
  EXPECT_EQ(ok(mannequin({{"fitmap", "stretch"}})).fitMap, "stretch");
  for (const char* kind : {"ease", "pressure"}) EXPECT_EQ(ok({{"fitmap", kind}}).fitMap, kind);
}

TEST(RenderRequest, AMadeBodyWearsUnderwearUnlessItIsTurnedOff) {
  const RenderRequest dressed = ok({{"outfit", "pencil:M"}});
  EXPECT_TRUE(dressed.underwear);
  EXPECT_EQ(dressed.canonical().find("underwear"), std::string::npos);  // the default: earlier tags unchanged
  EXPECT_EQ(ok({{"outfit", "pencil:M"}, {"underwear", "on"}}).canonical(), dressed.canonical());
  const RenderRequest bare = ok({{"outfit", "pencil:M"}, {"underwear", "off"}});
  EXPECT_FALSE(bare.underwear);
  EXPECT_EQ(bare.drapeKey(), dressed.drapeKey());  // inside the clearance: the same drape
  EXPECT_NE(bare.sceneKey(), dressed.sceneKey());  // but another picture
  EXPECT_NE(bare.canonical().find("&underwear=off"), std::string::npos);
  auto again = RenderRequest::parseCanonical(bare.canonical(), catalogue());
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
  EXPECT_FALSE(std::get<RenderRequest>(again).underwear);
  EXPECT_EQ(std::get<RenderRequest>(again).canonical(), bare.canonical());
  const ParameterError bad = refused({{"underwear", "yes"}});
  EXPECT_EQ(bad.parameter, "underwear");
  EXPECT_EQ(bad.accepted, "on (the default), off");
  const ParameterError scanned = refused(mannequin({{"underwear", "off"}}));
  EXPECT_EQ(scanned.parameter, "underwear");
  EXPECT_EQ(scanned.accepted, "no underwear with body=mannequin");
}

TEST(RenderRequest, ARefusalQuotesWholeCharacters) {
  // The answer is JSON: a value cut inside a character would not be UTF-8, its dump would
  // throw and the client get 500. "€" is 3 bytes: 22 of them cut at 64 bytes fall mid-character.
  std::string euros;
  for (int i = 0; i < 22; ++i) euros += "\xe2\x82\xac";
  for (const auto& [name, value] : QueryParameters{{"skin", euros}, {"outfit", "dress:" + euros}, {euros, "1"}}) {
    const ParameterError error = refused({{name, value}});
    EXPECT_EQ(error.value.size() % 3, name == euros ? 1u : 0u) << name;  // whole euros ("1" for the name's)
    EXPECT_LE(error.value.size(), 64u);
    const nlohmann::json answer = {{"error", error.error}, {"parameter", error.parameter}, {"value", error.value}};
    EXPECT_NO_THROW(answer.dump()) << name;
  }
  EXPECT_EQ(utf8Prefix(euros, 64), euros.substr(0, 63));
  EXPECT_EQ(utf8Prefix("abc", 64), "abc");
}

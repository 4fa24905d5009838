// A render request's parameters: defaults, canonical text that reads back to itself, and
// every class of bad parameter refused with the parameter, its value and what is accepted.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "serve/request/RenderRequest.h"

using namespace figment;
using namespace figment::serve;

namespace {

RenderRequest ok(const QueryParameters& parameters) {
  auto parsed = RenderRequest::parse(parameters);
  if (auto* error = std::get_if<ParameterError>(&parsed)) ADD_FAILURE() << error->parameter << ": " << error->error;
  return std::holds_alternative<RenderRequest>(parsed) ? std::get<RenderRequest>(parsed) : RenderRequest{};
}

ParameterError refused(const QueryParameters& parameters) {
  auto parsed = RenderRequest::parse(parameters);
  EXPECT_TRUE(std::holds_alternative<ParameterError>(parsed)) << "accepted";
  return std::holds_alternative<ParameterError>(parsed) ? std::get<ParameterError>(parsed) : ParameterError{};
}

}  // namespace

TEST(RenderRequest, NoParametersIsTheDefaultBodyInTheDress) {
  const RenderRequest request = ok({});
  EXPECT_EQ(request.canonical(),
            "stature=1.659&bust=0.891&waist=0.696&hips=0.939&skin=cc9473&pose=rest&outfit=dress:M:1f40b3"
            "&light=studio&view=0.0,0.0&size=800x600");
}

TEST(RenderRequest, CanonicalTextReadsBackToItself) {
  const RenderRequest request = ok({{"stature", "1.7204"},
                                    {"chest", "0.95"},
                                    {"skin", "tan"},
                                    {"outfit", "tshirt:L:2E7D32,skirt:S"},
                                    {"view", "-30,10.04"},
                                    {"size", "320x240"},
                                    {"light", "warm"},
                                    {"pose", "relaxed"}});
  EXPECT_EQ(request.canonical(),
            "stature=1.720&bust=0.950&waist=0.696&hips=0.939&skin=a86b45&pose=relaxed"
            "&outfit=tshirt:L:2e7d32,skirt:S:8c1f33&light=warm&view=330.0,10.0&size=320x240");
  auto again = RenderRequest::parseCanonical(request.canonical());
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
  EXPECT_EQ(std::get<RenderRequest>(again).canonical(), request.canonical());
}

TEST(RenderRequest, ColoursLightAndViewShareTheDrape) {
  const RenderRequest a = ok({{"outfit", "dress:M:111111"}, {"view", "back"}, {"light", "soft"}});
  const RenderRequest b = ok({{"outfit", "dress:M:222222"}});
  EXPECT_EQ(a.drapeKey(), b.drapeKey());
  EXPECT_NE(a.canonical(), b.canonical());
  EXPECT_NE(ok({{"outfit", "dress:L"}}).drapeKey(), b.drapeKey());  // the control: a size drapes anew
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
      {{{"outfit", "dress:XXS"}}, "outfit", "no size named XXS"},
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

namespace {

SizeChart womensChart() {
  return SizeChart(
      {{Sex::Female, "S", "36", 1.68, 0.84, 0.68, 0.92}, {Sex::Female, "M", "38", 1.68, 0.88, 0.72, 0.96}});
}

}  // namespace

TEST(RenderRequest, ASexMakesTheBodyMeasuredAndTheSizesTheCharts) {
  const SizeChart chart = womensChart();
  auto parsed = RenderRequest::parse({{"sex", "female"}, {"outfit", "pencil:38:FF0000"}}, &chart);
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(parsed));
  const RenderRequest& request = std::get<RenderRequest>(parsed);
  EXPECT_EQ(request.sex, "female");
  ASSERT_EQ(request.outfit.size(), 1u);
  EXPECT_EQ(request.outfit[0].size, "M");  // the chart's number, named by its letter code
  EXPECT_EQ(request.canonical(),
            "stature=1.659&bust=0.891&waist=0.696&hips=0.939&sex=female&skin=cc9473&pose=rest&outfit=pencil:M:ff0000"
            "&light=studio&view=0.0,0.0&size=800x600");
  auto again = RenderRequest::parseCanonical(request.canonical(), &chart);
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
  EXPECT_EQ(std::get<RenderRequest>(again).canonical(), request.canonical());
  EXPECT_NE(request.drapeKey().find("sex=female"), std::string::npos);
}

TEST(RenderRequest, AMeasuredBodyRefusesWhatItCannotWear) {
  const SizeChart chart = womensChart();
  const auto refusedWith = [&chart](const QueryParameters& parameters, const SizeChart* given) {
    auto parsed = RenderRequest::parse(parameters, given);
    EXPECT_TRUE(std::holds_alternative<ParameterError>(parsed));
    return std::holds_alternative<ParameterError>(parsed) ? std::get<ParameterError>(parsed) : ParameterError{};
  };
  EXPECT_EQ(refusedWith({{"sex", "female"}}, nullptr).error, "no size chart: measured bodies are off");
  EXPECT_EQ(refusedWith({{"sex", "x"}}, &chart).parameter, "sex");
  // The Mannequin's joints are not MakeHuman's rig: its poses are refused, naming the rig's.
  const ParameterError relaxed = refusedWith({{"sex", "female"}, {"pose", "relaxed"}}, &chart);
  EXPECT_EQ(relaxed.parameter, "pose");
  EXPECT_EQ(relaxed.accepted, "rest, arms-down, arm-raised, walking, sitting");
  EXPECT_EQ(refusedWith({{"pose", "sitting"}}, &chart).parameter, "pose");  // and the rig's for the Mannequin
  EXPECT_EQ(refusedWith({{"sex", "female"}, {"outfit", "pencil:XL"}}, &chart).error, "no size named XL");
  EXPECT_EQ(refusedWith({{"sex", "female"}, {"outfit", "cape:M"}}, &chart).error, "no style named cape");
  // Without a sex the chart changes nothing: the Mannequin's styles and sizes.
  EXPECT_EQ(refusedWith({{"outfit", "pencil:M"}}, &chart).error, "no style named pencil");
}

TEST(RenderRequest, AMeasuredBodysMeasurementsTakeTheSizeAdvicesRanges) {
  // MakeHuman's reach, as GET /api/fit accepts it: the chart's bodies widened by 8 cm each
  // side (here bust 0.76 to 0.96) and stature 1.45 to 1.95; not the Mannequin's ranges.
  const SizeChart chart = womensChart();
  const auto parsed = [&chart](const QueryParameters& parameters) { return RenderRequest::parse(parameters, &chart); };
  auto bust = parsed({{"sex", "female"}, {"bust", "1.00"}});
  ASSERT_TRUE(std::holds_alternative<ParameterError>(bust));
  EXPECT_EQ(std::get<ParameterError>(bust).parameter, "bust");
  EXPECT_EQ(std::get<ParameterError>(bust).value, "1.00");
  EXPECT_EQ(std::get<ParameterError>(bust).accepted, "0.76 to 0.96 (metres)");
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed({{"bust", "1.00"}})));  // the Mannequin's range
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed({{"sex", "female"}, {"stature", "1.93"}})));
  auto chest = parsed({{"sex", "female"}, {"chest", "0.70"}});
  ASSERT_TRUE(std::holds_alternative<ParameterError>(chest));
  EXPECT_EQ(std::get<ParameterError>(chest).parameter, "chest");
  EXPECT_EQ(refused({{"stature", "1.93"}}).parameter, "stature");
}

TEST(RenderRequest, APosedMeasuredBodyWearsOneGarmentAndSitsOnlyInATshirt) {
  const SizeChart chart = womensChart();
  const auto parsed = [&chart](const QueryParameters& parameters) { return RenderRequest::parse(parameters, &chart); };
  for (const char* pose : {"rest", "arms-down", "arm-raised", "walking", "sitting"}) {
    auto one = parsed({{"sex", "female"}, {"pose", pose}, {"outfit", "tshirt:M"}});
    ASSERT_TRUE(std::holds_alternative<RenderRequest>(one)) << pose;
    EXPECT_EQ(std::get<RenderRequest>(one).pose, pose);
    EXPECT_NE(std::get<RenderRequest>(one).drapeKey().find(std::string("pose=") + pose), std::string::npos);
  }
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed({{"sex", "female"}, {"outfit", "tshirt:M,pencil:M"}})));
  EXPECT_TRUE(std::holds_alternative<RenderRequest>(parsed({{"sex", "female"}, {"pose", "sitting"}, {"outfit", ""}})));
  for (const auto& [pose, outfit] : std::vector<std::pair<std::string, std::string>>{
           {"walking", "tshirt:M,pencil:M"}, {"arms-down", "pencil:S,tshirt:M"}, {"sitting", "pencil:M"}}) {
    auto refusal = parsed({{"sex", "female"}, {"pose", pose}, {"outfit", outfit}});
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
    if (k < 3) EXPECT_GT((k + 1) * (k + 1) * pixels, 4L * RequestLimits::kMaxPixels) << size;
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
  auto again = RenderRequest::parseCanonical(mapped.canonical());
  ASSERT_TRUE(std::holds_alternative<RenderRequest>(again));
  EXPECT_EQ(std::get<RenderRequest>(again).canonical(), mapped.canonical());
  EXPECT_EQ(ok({{"fitmap", "stretch"}, {"format", "glb"}}).canonical(), ok({{"format", "glb"}}).canonical());
  const ParameterError bad = refused({{"fitmap", "heat"}});
  EXPECT_EQ(bad.parameter, "fitmap");
  EXPECT_EQ(bad.accepted, "stretch, none; with sex also ease, pressure");
  // Ease and pressure measure from the skin as a mesh: a measured body's, not the Mannequin's.
  EXPECT_EQ(refused({{"fitmap", "ease"}}).error, "ease and pressure need a measured body (sex)");
  const SizeChart chart = womensChart();
  for (const char* kind : {"ease", "pressure"}) {
    auto parsed = RenderRequest::parse({{"sex", "female"}, {"fitmap", kind}}, &chart);
    ASSERT_TRUE(std::holds_alternative<RenderRequest>(parsed)) << kind;
    EXPECT_EQ(std::get<RenderRequest>(parsed).fitMap, kind);
  }
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

// A fit request's parameters: every one required, canonical text that reads back to itself
// (its kind travels beside it, never in it), and every class of bad parameter refused with
// the parameter, its value and what is accepted. Checked against the shipped catalogue, as
// the server checks them: a style is one it dresses a body of that sex in.

#include <gtest/gtest.h>

#include <cstdio>

#include "serve/request/FitRequest.h"
#include "support/ShippedCatalogue.h"

namespace test_FitRequest {

using namespace figment;
using namespace figment::serve;

namespace {

const GarmentCatalogue& chart() {
  return test::shippedCatalogue();
}

QueryParameters womansM() {
  return {{"sex", "female"}, {"style", "pencil"}, {"stature", "1.68"},
          {"bust", "0.88"},  {"waist", "0.72"},   {"hips", "0.9604"}};
}

ParameterError refused(const QueryParameters& parameters) {
  auto parsed = FitRequest::parse(parameters, chart());
  EXPECT_TRUE(std::holds_alternative<ParameterError>(parsed)) << "accepted";
  return std::holds_alternative<ParameterError>(parsed) ? std::get<ParameterError>(parsed) : ParameterError{};
}

QueryParameters with(const std::string& name, const std::string& value) {
  QueryParameters parameters = womansM();
  for (auto& [key, given] : parameters)
    if (key == name) given = value;
  return parameters;
}

}  // namespace

TEST(FitRequest, CanonicalTextReadsBackToItselfInMillimetres) {
  auto parsed = FitRequest::parse(womansM(), chart());
  ASSERT_TRUE(std::holds_alternative<FitRequest>(parsed));
  const std::string canonical = std::get<FitRequest>(parsed).canonical();
  EXPECT_EQ(canonical, "sex=female&style=pencil&stature=1.680&bust=0.880&waist=0.720&hips=0.960");
  auto again = FitRequest::parseCanonical(canonical, chart());
  ASSERT_TRUE(std::holds_alternative<FitRequest>(again));
  EXPECT_EQ(std::get<FitRequest>(again).canonical(), canonical);
}

TEST(FitRequest, ARendersCanonicalTextIsNotAFit) {
  EXPECT_TRUE(std::holds_alternative<ParameterError>(
      FitRequest::parseCanonical("stature=1.659&bust=0.891&waist=0.696&hips=0.939&skin=cc9473", chart())));
  EXPECT_TRUE(std::holds_alternative<ParameterError>(FitRequest::parseCanonical("stature=1.659", chart())));
}

TEST(FitRequest, RefusesEachBadParameterNamingItAndTheAcceptedRange) {
  EXPECT_EQ(refused(with("style", "cape")).parameter, "style");
  EXPECT_NE(refused(with("style", "cape")).accepted.find("pencil"), std::string::npos);
  EXPECT_EQ(refused(with("sex", "x")).accepted, "female, male");
  // A style not sold to the sex; one sewn from a pattern is advised as a cut one is.
  QueryParameters man = with("sex", "male");
  for (auto& [key, given] : man)
    if (key == "style") given = "dress";
  EXPECT_EQ(refused(man).error, "dress is not sold in male sizes");
  for (auto& [key, given] : man)
    if (key == "style") given = "sundress";
  EXPECT_EQ(refused(man).error, "sundress is not sold in male sizes");
  EXPECT_TRUE(std::holds_alternative<FitRequest>(FitRequest::parse(with("style", "tee"), chart())));
  // The ranges are the women's smallest and largest chart bodies, two 4 cm sizes beyond.
  const std::vector<ChartSize>& women = chart().chart().sizes(Sex::Female);
  char range[64];
  std::snprintf(range, sizeof range, "%.2f to %.2f (metres)", women.front().bust - 0.08, women.back().bust + 0.08);
  char under[16];
  std::snprintf(under, sizeof under, "%.3f", women.front().bust - 0.09);
  const ParameterError small = refused(with("bust", under));
  EXPECT_EQ(small.parameter, "bust");
  EXPECT_EQ(small.error, "out of range");
  EXPECT_EQ(small.accepted, range);
  EXPECT_EQ(refused(with("waist", "nan")).error, "not a number");
  EXPECT_EQ(refused(with("stature", "2.5")).parameter, "stature");
  QueryParameters missing = womansM();
  missing.pop_back();
  EXPECT_EQ(refused(missing).parameter, "hips");
  QueryParameters unknown = womansM();
  unknown.emplace_back("size", "M");
  EXPECT_EQ(refused(unknown).error, "unknown parameter");
  QueryParameters twice = womansM();
  twice.emplace_back("sex", "female");
  EXPECT_EQ(refused(twice).error, "given twice");
}

}  // namespace test_FitRequest

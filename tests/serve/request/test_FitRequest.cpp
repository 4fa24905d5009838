// A fit request's parameters: every one required, canonical text that reads back to itself
// (its kind travels beside it, never in it), and every class of bad parameter refused with
// the parameter, its value and what is accepted.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "serve/request/FitRequest.h"
#include "support/SmallSizeChart.h"

using namespace figment;
using namespace figment::serve;

namespace {

// Women's S and M, men's M and L.
SizeChart chart() {
  return test::smallSizeChart(2, 0, 2);
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
  const ParameterError small = refused(with("bust", "0.70"));  // the women's S less two sizes is 0.76
  EXPECT_EQ(small.parameter, "bust");
  EXPECT_EQ(small.error, "out of range");
  EXPECT_EQ(small.accepted, "0.76 to 0.96 (metres)");
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

TEST(FitRequest, ChoicesListTheChartsSizesPerStyleAndSex) {
  const nlohmann::json fit = FitRequest::choicesJson(chart());
  bool pencil = false;
  for (const nlohmann::json& style : fit["styles"]) {
    ASSERT_EQ(style["sizes"]["female"].size(), 2u);
    EXPECT_EQ(style["sizes"]["male"][1]["name"], "L");
    EXPECT_EQ(style["sizes"]["male"][1]["number"], "50");
    pencil = pencil || style["name"] == "pencil";
  }
  EXPECT_TRUE(pencil);
  EXPECT_DOUBLE_EQ(fit["measurements"]["female"]["waist"]["max"].get<double>(), 0.80);
}

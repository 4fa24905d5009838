#include "serve/request/FitRequest.h"

#include <algorithm>
#include <cstdio>
#include <map>

#include "io/GarmentCatalogue.h"
#include "serve/request/BodyMeasuresText.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/request/Utf8Text.h"

namespace figment::serve {

namespace {

const char* const kNames[] = {"sex", "style", "stature", "bust", "waist", "hips"};

ParameterError bad(const std::string& parameter, const std::string& value, const std::string& error,
                   const std::string& accepted) {
  return RequestParameters::refusal(parameter, value, error, accepted);
}

std::variant<std::map<std::string, std::string>, ParameterError> byName(const QueryParameters& parameters) {
  std::map<std::string, std::string> values;
  const std::string known = "sex, style, stature, bust, waist, hips";
  if (int(parameters.size()) > RequestLimits::kMaxParameters) return bad("", "", "too many parameters", "at most 16");
  for (const auto& [name, value] : parameters) {
    if (auto error = RequestParameters::textError(name, value)) return *error;
    if (std::find(std::begin(kNames), std::end(kNames), name) == std::end(kNames))
      return bad(Utf8Text::shown(name, 64), value, "unknown parameter", known);
    if (value.size() > RequestLimits::kMaxValueLength) return bad(name, value, "value too long", "at most 200 bytes");
    if (!values.emplace(name, value).second) return bad(name, value, "given twice", "each parameter once");
  }
  for (const char* name : kNames)
    if (!values.count(name)) return bad(name, "", "missing", "every one of " + known);
  return values;
}

}  // namespace

std::variant<FitRequest, ParameterError> FitRequest::parse(const QueryParameters& parameters,
                                                           const GarmentCatalogue& catalogue) {
  auto parsed = byName(parameters);
  if (auto* error = std::get_if<ParameterError>(&parsed)) return *error;
  const auto& values = std::get<std::map<std::string, std::string>>(parsed);
  FitRequest request;
  const std::string& sex = values.at("sex");
  if (sex != "female" && sex != "male") return bad("sex", sex, "no such sex", "female, male");
  request.sex = sex == "male" ? Sex::Male : Sex::Female;
  request.style = values.at("style");
  const SizeChart& chart = catalogue.chart();
  if (chart.sizes(request.sex).empty()) return bad("sex", sex, "the size chart has no sizes for it", "female, male");
  auto style = MadeBodyChoices::style(catalogue, request.sex, request.style, "style", request.style);
  if (auto* error = std::get_if<ParameterError>(&style)) return *error;
  double* fields[] = {&request.body.stature, &request.body.bust, &request.body.waist, &request.body.hips};
  const std::vector<MeasureRange> accepted = BodyMeasuresText::ranges(chart, request.sex);
  for (size_t i = 0; i < accepted.size(); ++i)
    if (auto error = BodyMeasuresText::read(accepted[i].name, values.at(accepted[i].name), accepted[i], *fields[i]))
      return *error;
  return request;
}

std::vector<std::string> FitRequest::parameterNames() {
  return {std::begin(kNames), std::end(kNames)};
}

std::string FitRequest::canonical() const {
  char text[160];
  std::snprintf(text, sizeof text, "sex=%s&style=%s&stature=%.3f&bust=%.3f&waist=%.3f&hips=%.3f", sexName(sex),
                style.c_str(), body.stature, body.bust, body.waist, body.hips);
  return text;
}

std::variant<FitRequest, ParameterError> FitRequest::parseCanonical(const std::string& text,
                                                                    const GarmentCatalogue& catalogue) {
  return parse(RequestParameters::split(text), catalogue);
}

}  // namespace figment::serve

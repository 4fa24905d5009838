#include "serve/request/FitRequest.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "serve/request/MeasuredPoses.h"
#include "serve/request/Utf8Text.h"
#include "sim/garment/GarmentStyle.h"

namespace figment::serve {

namespace {

const char* const kNames[] = {"sex", "style", "stature", "bust", "waist", "hips"};
constexpr double kBeyondChart = 0.08;                     // m: two of the chart's 4 cm steps each side
constexpr double kMinStature = 1.45, kMaxStature = 1.95;  // m: MakeHuman's adults at default age

ParameterError bad(const std::string& parameter, const std::string& value, const std::string& error,
                   const std::string& accepted) {
  return {error, parameter, Utf8Text::shown(value, 64), accepted};
}

// A plain decimal number, nothing before or after it; no inf or nan.
bool number(const std::string& text, double& value) {
  if (text.empty() || text.size() > 32) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::fixed);
  return ec == std::errc() && ptr == end && std::isfinite(value);
}

double rounded(double metres) {
  return std::round(metres * 1000.0) / 1000.0;  // mm
}

std::variant<std::map<std::string, std::string>, ParameterError> byName(const RenderRequest::Parameters& parameters) {
  std::map<std::string, std::string> values;
  const std::string known = "sex, style, stature, bust, waist, hips";
  if (int(parameters.size()) > RequestLimits::kMaxParameters) return bad("", "", "too many parameters", "at most 16");
  for (const auto& [name, value] : parameters) {
    if (auto error = RenderRequest::textError(name, value)) return *error;
    if (std::find(std::begin(kNames), std::end(kNames), name) == std::end(kNames))
      return bad(Utf8Text::shown(name, 64), value, "unknown parameter", known);
    if (value.size() > RequestLimits::kMaxValueLength) return bad(name, value, "value too long", "at most 200 bytes");
    if (!values.emplace(name, value).second) return bad(name, value, "given twice", "each parameter once");
  }
  for (const char* name : kNames)
    if (!values.count(name)) return bad(name, "", "missing", "every one of " + known);
  return values;
}

std::optional<ParameterError> measurement(const MeasureRange& range, const std::string& value, double& out) {
  char accepted[96];
  std::snprintf(accepted, sizeof accepted, "%.2f to %.2f (metres)", range.minimum, range.maximum);
  double v = 0;
  if (!number(value, v)) return bad(range.name, value, "not a number", accepted);
  if (v < range.minimum || v > range.maximum) return bad(range.name, value, "out of range", accepted);
  out = rounded(v);
  return std::nullopt;
}

}  // namespace

std::vector<MeasureRange> FitRequest::ranges(const SizeChart& chart, Sex sex) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  const ChartSize& small = sizes.front();
  const ChartSize& large = sizes.back();
  return {{"stature", kMinStature, kMaxStature, 0},
          {"bust", rounded(small.bust - kBeyondChart), rounded(large.bust + kBeyondChart), 0},
          {"waist", rounded(small.waist - kBeyondChart), rounded(large.waist + kBeyondChart), 0},
          {"hips", rounded(small.hip - kBeyondChart), rounded(large.hip + kBeyondChart), 0}};
}

std::variant<FitRequest, ParameterError> FitRequest::parse(const RenderRequest::Parameters& parameters,
                                                           const SizeChart& chart) {
  auto parsed = byName(parameters);
  if (auto* error = std::get_if<ParameterError>(&parsed)) return *error;
  const auto& values = std::get<std::map<std::string, std::string>>(parsed);
  FitRequest request;
  const std::string& sex = values.at("sex");
  if (sex != "female" && sex != "male") return bad("sex", sex, "no such sex", "female, male");
  request.sex = sex == "male" ? Sex::Male : Sex::Female;
  request.style = values.at("style");
  if (!findStyle(request.style)) return bad("style", request.style, "no such style", styleNames());
  if (chart.sizes(request.sex).empty()) return bad("sex", sex, "the size chart has no sizes for it", "female, male");
  double* fields[] = {&request.body.stature, &request.body.bust, &request.body.waist, &request.body.hips};
  const std::vector<MeasureRange> accepted = ranges(chart, request.sex);
  for (size_t i = 0; i < accepted.size(); ++i)
    if (auto error = measurement(accepted[i], values.at(accepted[i].name), *fields[i])) return *error;
  return request;
}

std::vector<std::string> FitRequest::parameterNames() {
  return {std::begin(kNames), std::end(kNames)};
}

std::string FitRequest::canonical() const {
  char text[160];
  std::snprintf(text, sizeof text, "sex=%s&style=%s&stature=%.3f&bust=%.3f&waist=%.3f&hips=%.3f", sexName(sex),
                style.c_str(), body.stature, body.bust, body.waist, body.hips);
  return kPrefix + std::string(text);
}

bool FitRequest::isFit(const std::string& canonical) {
  return canonical.rfind(kPrefix, 0) == 0;
}

std::variant<FitRequest, ParameterError> FitRequest::parseCanonical(const std::string& text, const SizeChart& chart) {
  if (!isFit(text)) return bad("", text, "not a fit request", kPrefix);
  return parse(RenderRequest::splitCanonical(text, std::string(kPrefix).size()), chart);
}

nlohmann::json FitRequest::catalogueJson(const SizeChart& chart) {
  nlohmann::json sizes = nlohmann::json::object(), measures = nlohmann::json::object();
  for (const Sex sex : {Sex::Female, Sex::Male}) {
    nlohmann::json list = nlohmann::json::array(), ranged = nlohmann::json::object();
    for (const ChartSize& size : chart.sizes(sex))
      list.push_back({{"name", size.name},
                      {"number", size.number},
                      {"stature", size.stature},
                      {"bust", size.bust},
                      {"waist", size.waist},
                      {"hips", size.hip}});
    sizes[sexName(sex)] = list;
    if (!chart.sizes(sex).empty())
      for (const MeasureRange& range : ranges(chart, sex))
        ranged[range.name] = {{"unit", "m"}, {"min", range.minimum}, {"max", range.maximum}};
    measures[sexName(sex)] = ranged;
  }
  nlohmann::json styles = nlohmann::json::array();
  for (const figment::GarmentStyle& style : garmentStyles())
    styles.push_back({{"name", style.name}, {"about", style.about}, {"sizes", sizes}});
  nlohmann::json poses = nlohmann::json::array();  // a measured body's (GET /api/render with sex)
  for (const MeasuredPose& pose : MeasuredPoses::all()) poses.push_back(pose.name);
  return {{"styles", styles}, {"measurements", measures}, {"poses", poses}};
}

}  // namespace figment::serve

#include "serve/request/MadeBodyChoices.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "io/GarmentCatalogue.h"
#include "serve/request/BodyMeasuresText.h"
#include "serve/request/MeasuredPoses.h"
#include "serve/request/Utf8Text.h"

namespace figment::serve {

namespace {

double mm(double metres) {
  return std::round(metres * 1000.0) / 1000.0;
}

// The size a body of `sex` is by default: the chart's M, else its middle size.
const ChartSize& defaultSize(const SizeChart& chart, Sex sex) {
  const std::vector<ChartSize>& sizes = chart.sizes(sex);
  if (sizes.empty()) throw std::invalid_argument(std::string("the size chart has no ") + sexName(sex) + " sizes");
  const int m = chart.find(sex, "M");
  return sizes[m >= 0 ? size_t(m) : sizes.size() / 2];
}

}  // namespace

std::shared_ptr<const GarmentCatalogue> MadeBodyChoices::readCatalogue(const std::string& scenesFolder) {
  return std::make_shared<const GarmentCatalogue>(cataloguePath(scenesFolder));
}

std::vector<const CatalogueStyle*> MadeBodyChoices::styles(const GarmentCatalogue& catalogue, Sex sex) {
  std::vector<const CatalogueStyle*> out;
  for (const CatalogueStyle& style : catalogue.styles())
    if (!style.sizes(sex).empty()) out.push_back(&style);
  return out;
}

std::string MadeBodyChoices::styleNames(const GarmentCatalogue& catalogue, Sex sex) {
  std::string names;
  for (const CatalogueStyle* style : styles(catalogue, sex)) names += (names.empty() ? "" : ", ") + style->name;
  return names;
}

std::variant<const CatalogueStyle*, ParameterError> MadeBodyChoices::style(const GarmentCatalogue& catalogue, Sex sex,
                                                                           const std::string& name,
                                                                           const std::string& parameter,
                                                                           const std::string& value) {
  const std::string accepted = std::string(sexName(sex)) + " styles " + styleNames(catalogue, sex);
  const CatalogueStyle* style = catalogue.style(name);
  if (!style)
    return RequestParameters::refusal(parameter, value, "no style named " + Utf8Text::shown(name, 32), accepted);
  if (style->sizes(sex).empty())
    return RequestParameters::refusal(parameter, value, name + " is not sold in " + sexName(sex) + " sizes", accepted);
  return style;
}

BodyMeasures MadeBodyChoices::defaultBody(const GarmentCatalogue& catalogue, Sex sex) {
  const ChartSize& size = defaultSize(catalogue.chart(), sex);
  return {mm(size.stature), mm(size.bust), mm(size.waist), mm(size.hip)};
}

std::pair<std::string, std::string> MadeBodyChoices::defaultGarment(const GarmentCatalogue& catalogue, Sex sex) {
  const std::vector<const CatalogueStyle*> sold = styles(catalogue, sex);
  if (sold.empty())
    throw std::invalid_argument(std::string("the catalogue sells no style in ") + sexName(sex) + " sizes");
  const std::string size = defaultSize(catalogue.chart(), sex).name;
  const std::vector<std::string>& sizes = sold.front()->sizes(sex);
  const bool cut = std::find(sizes.begin(), sizes.end(), size) != sizes.end();
  return {sold.front()->name, cut ? size : sizes[sizes.size() / 2]};
}

nlohmann::json MadeBodyChoices::toJson(const GarmentCatalogue& catalogue) {
  const SizeChart& chart = catalogue.chart();
  nlohmann::json styles = nlohmann::json::array();
  for (const CatalogueStyle& style : catalogue.styles()) {
    nlohmann::json sizes = nlohmann::json::object();
    for (const Sex sex : {Sex::Female, Sex::Male})
      if (!style.sizes(sex).empty()) sizes[sexName(sex)] = style.sizes(sex);
    styles.push_back({{"name", style.name},
                      {"about", style.about},
                      {"sewn", style.sewn()},
                      {"sizes", sizes},
                      {"colours", style.colours},
                      {"defaultColour", style.colours.front()}});
  }
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
    if (chart.sizes(sex).empty()) continue;
    const BodyMeasures body = defaultBody(catalogue, sex);
    const double defaults[] = {body.stature, body.bust, body.waist, body.hips};
    const std::vector<MeasureRange> ranges = BodyMeasuresText::ranges(chart, sex);
    for (size_t i = 0; i < ranges.size(); ++i)
      ranged[ranges[i].name] = {
          {"unit", "m"}, {"min", ranges[i].minimum}, {"max", ranges[i].maximum}, {"default", defaults[i]}};
    measures[sexName(sex)] = ranged;
  }
  nlohmann::json poses = nlohmann::json::array();
  for (const MeasuredPose& pose : MeasuredPoses::all()) poses.push_back(pose.name);
  // The base layer (RenderRequest::underwear): on unless the shopper turns it off.
  const nlohmann::json underwear = {{"values", {"on", "off"}}, {"default", "on"}};
  return {{"styles", styles}, {"sizes", sizes}, {"measurements", measures}, {"poses", poses}, {"underwear", underwear}};
}

}  // namespace figment::serve

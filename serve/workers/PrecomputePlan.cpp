#include "serve/workers/PrecomputePlan.h"

#include <set>
#include <sstream>

#include "io/GarmentCatalogue.h"
#include "serve/request/MadeBodyChoices.h"
#include "serve/request/RenderRequest.h"

namespace figment::serve {

namespace {

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// %XX and + decoded, as a query string's are.
std::string decoded(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hexDigit(text[i + 1]) >= 0 && hexDigit(text[i + 2]) >= 0) {
      out += char(hexDigit(text[i + 1]) * 16 + hexDigit(text[i + 2]));
      i += 2;
    } else {
      out += text[i] == '+' ? ' ' : text[i];
    }
  }
  return out;
}

QueryParameters parametersOf(const std::string& query) {
  QueryParameters parameters;
  std::stringstream in(query);
  for (std::string pair; std::getline(in, pair, '&');) {
    if (pair.empty()) continue;
    const size_t eq = pair.find('=');
    parameters.emplace_back(decoded(pair.substr(0, eq)), eq == std::string::npos ? "" : decoded(pair.substr(eq + 1)));
  }
  return parameters;
}

// The canonical text of `parameters`, or the error as "parameter=value: error (accepted)".
std::variant<std::string, std::string> canonicalOf(const QueryParameters& parameters,
                                                   const GarmentCatalogue* catalogue) {
  auto parsed = RenderRequest::parse(parameters, catalogue);
  if (const auto* error = std::get_if<ParameterError>(&parsed))
    return std::variant<std::string, std::string>(
        std::in_place_index<1>, (error->parameter.empty() ? "" : error->parameter + "=" + error->value + ": ") +
                                    error->error + (error->accepted.empty() ? "" : " (" + error->accepted + ")"));
  return std::variant<std::string, std::string>(std::in_place_index<0>, std::get<RenderRequest>(parsed).canonical());
}

void addOnce(PrecomputePlan::Requests& requests, std::set<std::string>& seen, std::string request) {
  if (seen.insert(request).second) requests.push_back(std::move(request));
}

}  // namespace

std::variant<PrecomputePlan::Requests, std::string> PrecomputePlan::fromLines(const std::string& text,
                                                                              const std::string& fileName,
                                                                              const GarmentCatalogue* catalogue) {
  Requests requests;
  std::set<std::string> seen;
  std::stringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    auto canonical = canonicalOf(parametersOf(line.substr(start)), catalogue);
    if (canonical.index() == 1) return fileName + ":" + std::to_string(number) + ": " + std::get<1>(canonical);
    addOnce(requests, seen, std::get<0>(canonical));
  }
  return requests;
}

std::variant<PrecomputePlan::Requests, std::string> PrecomputePlan::fromCatalogue(const Grid& grid,
                                                                                  const GarmentCatalogue& catalogue) {
  std::vector<std::string> sexes = grid.sexes, poses = grid.poses, views = grid.views, bodies = grid.bodies;
  if (sexes.empty())
    for (const Sex sex : {Sex::Female, Sex::Male})
      if (!MadeBodyChoices::styles(catalogue, sex).empty()) sexes.push_back(sexName(sex));
  if (poses.empty()) poses.push_back("rest");
  if (views.empty()) views.push_back("front");
  if (bodies.empty()) bodies.push_back("");
  Requests requests;
  std::set<std::string> seen;
  for (const std::string& sexText : sexes) {
    if (sexText != "female" && sexText != "male") return "--sex " + sexText + ": not female or male";
    const Sex sex = sexText == "male" ? Sex::Male : Sex::Female;
    for (const std::string& body : bodies) {
      QueryParameters measures = {{"sex", sexText}};
      std::stringstream in(body);
      for (const char* name : {"stature", "bust", "waist", "hips"})
        if (std::string value; std::getline(in, value, ',')) measures.emplace_back(name, value);
      if (!body.empty() && measures.size() != 5) return "--body " + body + ": not STATURE,BUST,WAIST,HIPS (metres)";
      for (const CatalogueStyle* style : MadeBodyChoices::styles(catalogue, sex))
        for (const std::string& size : style->sizes(sex))
          for (const std::string& pose : poses)
            for (const std::string& view : views) {
              if (style->sewn() && pose != "rest") continue;  // sewn standing (RenderRequest)
              QueryParameters parameters = measures;
              parameters.insert(parameters.end(), {{"outfit", style->name + ":" + size + ":" + style->colours.front()},
                                                   {"pose", pose},
                                                   {"view", view},
                                                   {"size", grid.size}});
              auto canonical = canonicalOf(parameters, &catalogue);
              if (canonical.index() == 1) return std::get<1>(canonical);
              addOnce(requests, seen, std::get<0>(canonical));
            }
    }
  }
  return requests;
}

}  // namespace figment::serve

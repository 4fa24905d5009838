#include "serve/workers/PrecomputePlan.h"

#include <set>
#include <sstream>

#include "serve/request/RenderRequest.h"
#include "serve/request/ShopperChoices.h"

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
std::variant<std::string, std::string> canonicalOf(const QueryParameters& parameters) {
  auto parsed = RenderRequest::parse(parameters);
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
                                                                              const std::string& fileName) {
  Requests requests;
  std::set<std::string> seen;
  std::stringstream in(text);
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#') continue;
    auto canonical = canonicalOf(parametersOf(line.substr(start)));
    if (canonical.index() == 1) return fileName + ":" + std::to_string(number) + ": " + std::get<1>(canonical);
    addOnce(requests, seen, std::get<0>(canonical));
  }
  return requests;
}

std::variant<PrecomputePlan::Requests, std::string> PrecomputePlan::fromCatalogue(const Grid& grid) {
  std::vector<std::string> poses = grid.poses, views = grid.views, bodies = grid.bodies;
  if (poses.empty())
    for (const Pose& pose : ShopperChoices::poses()) poses.push_back(pose.name);
  if (views.empty()) views.push_back("front");
  if (bodies.empty()) bodies.push_back("");
  Requests requests;
  std::set<std::string> seen;
  for (const std::string& body : bodies) {
    QueryParameters measures;
    std::stringstream in(body);
    for (const char* name : {"stature", "bust", "waist", "hips"})
      if (std::string value; std::getline(in, value, ',')) measures.emplace_back(name, value);
    if (!body.empty() && measures.size() != 4) return "--body " + body + ": not STATURE,BUST,WAIST,HIPS (metres)";
    for (const GarmentStyle& style : ShopperChoices::styles())
      for (const GarmentSize& size : ShopperChoices::sizes())
        for (const std::string& pose : poses)
          for (const std::string& view : views) {
            QueryParameters parameters = measures;
            parameters.insert(parameters.end(), {{"outfit", style.name + ":" + size.name + ":" + style.defaultColour},
                                                 {"pose", pose},
                                                 {"view", view},
                                                 {"size", grid.size}});
            auto canonical = canonicalOf(parameters);
            if (canonical.index() == 1) return std::get<1>(canonical);
            addOnce(requests, seen, std::get<0>(canonical));
          }
  }
  return requests;
}

}  // namespace figment::serve

#pragma once
// What figment-precompute puts on the work queue (serve/workers/JobQueue.h): render requests in
// their canonical text, either one per line of a file (query strings as GET /api/render
// takes them) or the catalogue's grid: every style in every size, in its default colour,
// on each body, pose and view asked for. Each request is checked as the server checks
// one; a bad one stops the whole plan with one line naming it (nothing is queued).

#include <string>
#include <variant>
#include <vector>

namespace figment::serve {

class PrecomputePlan {
 public:
  using Requests = std::vector<std::string>;  // canonical texts, each once, in the order met

  // One request per line of `text` read from `fileName`; blank lines and lines starting
  // with # are skipped. Or "FILE:LINE: what is wrong".
  static std::variant<Requests, std::string> fromLines(const std::string& text, const std::string& fileName);

  struct Grid {
    std::vector<std::string> bodies;  // "STATURE,BUST,WAIST,HIPS" in metres; none: the default body
    std::vector<std::string> poses;   // none: every pose of ShopperChoices
    std::vector<std::string> views;   // as the view parameter takes them; none: front
    std::string size = "800x600";     // WxH
  };
  // Every style × size of the catalogue in its default colour, × bodies × poses × views.
  static std::variant<Requests, std::string> fromCatalogue(const Grid& grid);
};

}  // namespace figment::serve
